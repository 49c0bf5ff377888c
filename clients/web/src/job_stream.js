// Follows one job's event stream. EventSource reconnects by itself with Last-Event-ID, and the
// service then sends only what was missed (and the current mesh again if that was missed), so a
// dropped connection costs nothing here. The stream is closed after `done`: the service ends it
// then, and EventSource would otherwise reconnect.
import { decodeEvent, EVENT_KINDS } from "./events.js";

/// `handlers`: { mesh, radiosity, progress, done, error } (each optional), called with decoded
/// events, and `error` with an Error when the stream fails for good or an event is malformed.
/// Returns { close() }.
export function followJob(jobId, handlers, EventSourceType = globalThis.EventSource) {
    const source = new EventSourceType(`v1/jobs/${encodeURIComponent(jobId)}/events`);
    let closed = false;
    const close = () => {
        closed = true;
        source.close();
    };
    for (const kind of EVENT_KINDS) {
        source.addEventListener(kind, (event) => {
            if (closed) return;
            let decoded;
            try {
                decoded = decodeEvent(kind, event.data);
            } catch (e) {
                close();
                handlers.error?.(e);
                return;
            }
            if (kind === "done") close();
            handlers[kind]?.(decoded);
        });
    }
    source.addEventListener("error", () => {
        // CONNECTING: EventSource retries on its own. CLOSED: an answer it will not retry.
        if (!closed && source.readyState === EventSourceType.CLOSED) {
            close();
            handlers.error?.(new Error(`the event stream of job ${jobId} failed`));
        }
    });
    return { close };
}
