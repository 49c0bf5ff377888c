// Follows one job's event stream. EventSource reconnects by itself with Last-Event-ID, and the
// service then sends only what was missed (and the current mesh again if that was missed), so a
// dropped connection costs nothing here. The stream is closed after `done`: the service ends it
// then, and EventSource would otherwise reconnect.
import { decodeEvent, EVENT_KINDS, EventFormatError } from "./events.js";

/// `handlers`: { open, mesh, radiosity, progress, done, error } (each optional), called with
/// decoded events, `open` when the service has answered (events from then on are not missed),
/// and `error` with an Error when the stream fails for good or an event is malformed.
/// A `radiosity` event that repeats earlier values (`valuesEvent`) gets them back here, so the
/// handler always sees both arrays. Returns { close() }.
export function followJob(jobId, handlers, EventSourceType = globalThis.EventSource) {
    const source = new EventSourceType(`v1/jobs/${encodeURIComponent(jobId)}/events`);
    let closed = false;
    const close = () => {
        closed = true;
        source.close();
    };
    // The last radiosity values the stream carried, and the id of their event.
    let values = null;
    for (const kind of EVENT_KINDS) {
        source.addEventListener(kind, (event) => {
            if (closed) return;
            let decoded;
            try {
                decoded = decodeEvent(kind, event.data);
                if (kind === "radiosity") values = withValues(decoded, event.lastEventId, values);
            } catch (e) {
                close();
                handlers.error?.(e);
                return;
            }
            if (kind === "done") close();
            handlers[kind]?.(decoded);
        });
    }
    source.addEventListener("open", () => {
        if (!closed) handlers.open?.();
    });
    source.addEventListener("error", () => {
        // CONNECTING: EventSource retries on its own. CLOSED: an answer it will not retry.
        if (!closed && source.readyState === EventSourceType.CLOSED) {
            close();
            handlers.error?.(new Error(`the event stream of job ${jobId} failed`));
        }
    });
    return { close };
}

/// Fills a repeat's arrays from `values` (the last event that had some); returns what is now the
/// last values. Throws EventFormatError when the repeat names values this stream never had.
function withValues(radiosity, eventId, values) {
    if (radiosity.valuesEvent === null) {
        return { id: String(eventId), radiosity };
    }
    if (values === null || values.id !== String(radiosity.valuesEvent)) {
        throw new EventFormatError(
            `malformed event: radiosity repeats the values of event ${radiosity.valuesEvent}, which this stream did not carry`,
        );
    }
    radiosity.triangleRadiosity = values.radiosity.triangleRadiosity;
    radiosity.vertexRadiosity = values.radiosity.vertexRadiosity;
    return values;
}
