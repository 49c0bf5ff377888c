// The viewer: open an example or drop a scene (with its files), submit it to radiantd, follow
// the job's events — progress, the patch mesh, the radiosity as it converges — and show the
// result's sensors and work-plane table; cancel; reopen past jobs.
import "./style.css";
import { cancelJob, getJob, getResult, listJobs, submitJob } from "./api.js";
import { ErrorPanel } from "./error_panel.js";
import { followJob } from "./job_stream.js";
import { renderJobs } from "./jobs_list.js";
import { Legend } from "./legend.js";
import { RoomView } from "./room_view.js";
import { droppedFileReader, SceneFileError, sceneBody, urlReader } from "./scene_files.js";
import { sensorLayouts } from "./sensor_geometry.js";
import { renderSensorTable } from "./sensor_table.js";

const $ = (selector) => document.querySelector(selector);
const ACTIVE = new Set(["queued", "running"]);
/// The sensor preview of a running job is read at most this often (it changes about once a second).
const RESULT_POLL_MS = 1000;
const NAMES_KEY = "radiant.jobNames";

const view = new RoomView($("#view"));
const legend = new Legend($("#legend"));
const errors = new ErrorPanel($("#errors"));

/// What tests and the console can read: the open job and what the view shows of it.
const state = {
    jobId: null,
    status: null,
    following: false, // the job's event stream is open
    meshVersions: [],
    vertices: 0,
    snapshotVersion: null,
    resultStatus: null,
};
window.radiantViewer = { state, project: (p) => view.project(p) };

let loaded = null; // the scene ready to submit: {name, scene, body, inlined}
let stream = null;
let token = 0; // which openJob() call the async answers belong to
let lastResultPoll = 0;
const scenes = new Map(); // job id → the scene this page sent (for its sensors' points)
const names = JSON.parse(localStorage.getItem(NAMES_KEY) || "{}");

function redraw() {
    legend.show(view.legend());
}

// --- loading a scene ---------------------------------------------------------------------

async function loadScene(name, text, read) {
    errors.clear();
    let parsed = null;
    try {
        parsed = JSON.parse(text);
    } catch {
        // The service's invalid_json answer says where; the text is sent as it is.
    }
    try {
        const { scene, body } = await sceneBody(text, read);
        const inlined = body !== text;
        loaded = { name: scene?.name || name, scene, body };
        showLoaded(scene, inlined);
    } catch (e) {
        loaded = null;
        showLoaded(null, false);
        if (e instanceof SceneFileError) errors.show(e, parsed);
        else errors.show({ message: e.message }, null);
    }
}

function showLoaded(scene, inlined) {
    const summary = $("#scene-summary");
    $("#submit").disabled = loaded === null;
    if (!loaded) {
        summary.textContent = "";
        return;
    }
    const count = (key) => (Array.isArray(scene?.[key]) ? scene[key].length : 0);
    const counted = (key, noun) => `${count(key)} ${noun}${count(key) === 1 ? "" : "s"}`;
    if (!scene) {
        summary.textContent = `${loaded.name} (not a JSON object: the service will say why)`;
        return;
    }
    const parts = [
        counted("surfaces", "surface"),
        counted("luminaires", "luminaire"),
        counted("sensors", "sensor set"),
    ];
    if (scene.units) parts.push(`in ${scene.units}`);
    summary.textContent = `${loaded.name}: ${parts.join(", ")}${inlined ? " (files inlined)" : ""}`;
}

async function loadExamples() {
    const select = $("#examples");
    try {
        const response = await fetch("examples/index.json");
        const examples = await response.json();
        select.replaceChildren(
            ...examples.map((e) =>
                Object.assign(document.createElement("option"), {
                    value: e.path,
                    textContent: e.name,
                }),
            ),
        );
    } catch {
        select.replaceChildren(
            Object.assign(document.createElement("option"), {
                textContent: "no examples installed",
            }),
        );
        select.disabled = true;
        $("#open-example").disabled = true;
    }
}

async function openExample() {
    const path = $("#examples").value;
    const url = new URL(`examples/${path}`, document.baseURI);
    const response = await fetch(url);
    await loadScene(
        path
            .split("/")
            .pop()
            .replace(/\.json$/, ""),
        await response.text(),
        urlReader(url),
    );
}

/// Dropped or picked files: the scene is the .json that says it is one (else the first .json);
/// the others are the files it may name.
async function loadFiles(fileList) {
    const files = [...fileList];
    const candidates = files.filter((f) => f.name.toLowerCase().endsWith(".json"));
    if (!candidates.length) {
        errors.show(
            { message: "drop a scene .json file (with the IES, OBJ or glTF files it names)" },
            null,
        );
        return;
    }
    let chosen = candidates[0];
    let text = await chosen.text();
    for (const f of candidates) {
        const t = f === chosen ? text : await f.text();
        if (/"format"\s*:\s*"radiant-scene\//.test(t)) {
            chosen = f;
            text = t;
            break;
        }
    }
    await loadScene(chosen.name.replace(/\.json$/i, ""), text, droppedFileReader(files));
}

// --- jobs ---------------------------------------------------------------------------------

async function submit() {
    if (!loaded) return;
    errors.clear();
    $("#submit").disabled = true;
    try {
        const { id } = await submitJob(loaded.body);
        names[id] = loaded.name;
        localStorage.setItem(NAMES_KEY, JSON.stringify(names));
        scenes.set(id, loaded.scene);
        await openJob(id);
    } catch (e) {
        errors.show(e, loaded.scene);
    } finally {
        $("#submit").disabled = loaded === null;
    }
    refreshJobs();
}

function setStatus(status) {
    state.status = status;
    const element = $("#job-status");
    element.textContent = status ?? "";
    element.className = `badge ${status ?? ""}`;
    $("#cancel").disabled = !ACTIVE.has(status);
}

function showProgress({ stage, fraction, errorEstimate, elapsedSeconds }) {
    const scene = scenes.get(state.jobId);
    const tolerance = scene?.settings?.tolerance ?? 0.01;
    if (Number.isFinite(fraction))
        $("#progress-bar").style.width = `${Math.round(100 * Math.min(1, Math.max(0, fraction)))}%`;
    const parts = [];
    if (stage) parts.push(stage);
    if (Number.isFinite(fraction)) parts.push(`${Math.round(100 * fraction)} %`);
    if (Number.isFinite(errorEstimate) && errorEstimate > 0) {
        const percent = 100 * errorEstimate;
        parts.push(
            `error ≈ ${percent > 100 ? "> 100" : percent.toPrecision(2)} % (target ${100 * tolerance} %)`,
        );
    }
    if (Number.isFinite(elapsedSeconds)) parts.push(`${elapsedSeconds.toFixed(1)} s`);
    $("#progress-text").textContent = parts.join(" · ");
    $("#progress").dataset.errorEstimate = String(errorEstimate ?? "");
}

async function showResult(id, mine) {
    let result;
    try {
        result = await getResult(id);
    } catch {
        return; // queued, or cancelled before it had a result
    }
    if (mine !== token) return;
    const layouts = sensorLayouts(result, scenes.get(id));
    view.setSensors(
        layouts,
        (result.sensors ?? []).map((s) => s.illuminance ?? []),
    );
    renderSensorTable($("#sensor-table"), result);
    if (result.status !== "running") {
        state.resultStatus = result.status;
        $("#result-status").textContent =
            `result: ${result.status}` +
            (Number.isFinite(result.stats?.error_estimate)
                ? `, error estimate ${(100 * result.stats.error_estimate).toPrecision(2)} %`
                : "");
    }
    redraw();
}

async function openJob(id) {
    const mine = ++token;
    stream?.close();
    stream = null;
    view.clear();
    renderSensorTable($("#sensor-table"), null);
    Object.assign(state, {
        jobId: id,
        following: false,
        meshVersions: [],
        vertices: 0,
        snapshotVersion: null,
        resultStatus: null,
    });
    $("#job-id").textContent = names[id] ? `${names[id]} (${id.slice(0, 8)})` : id;
    $("#result-status").textContent = "";
    $("#progress-bar").style.width = "0%";
    $("#progress-text").textContent = "";
    $("#job").hidden = false;
    redraw();
    try {
        const job = await getJob(id);
        if (mine !== token) return;
        setStatus(job.status);
        showProgress({
            ...job.progress,
            errorEstimate: job.progress?.error_estimate,
            elapsedSeconds: job.progress?.elapsed_seconds,
        });
    } catch (e) {
        errors.show(e, null);
        return;
    }
    const pollResult = () => {
        const now = performance.now();
        if (now - lastResultPoll < RESULT_POLL_MS) return;
        lastResultPoll = now;
        showResult(id, mine);
    };
    stream = followJob(id, {
        open: () => (state.following = true),
        mesh: (mesh) => {
            view.setMesh(mesh);
            state.meshVersions.push(mesh.meshVersion);
            state.vertices = mesh.positions.length / 3;
        },
        radiosity: (r) => {
            if (view.setRadiosity(r)) state.snapshotVersion = r.version;
            showProgress(r);
            redraw();
            pollResult();
        },
        progress: (p) => {
            setStatus(p.status);
            showProgress(p);
        },
        done: async ({ status, error }) => {
            setStatus(status);
            if (status === "done") $("#progress-bar").style.width = "100%";
            if (error) errors.show({ code: status, message: error }, null);
            await showResult(id, mine);
            refreshJobs();
        },
        error: (e) => errors.show({ message: e.message }, null),
    });
}

async function refreshJobs() {
    try {
        const { jobs } = await listJobs(20);
        renderJobs($("#jobs"), jobs, { currentId: state.jobId, names, open: openJob });
    } catch (e) {
        $("#jobs").replaceChildren(
            Object.assign(document.createElement("li"), { textContent: e.message }),
        );
    }
}

// --- wiring -------------------------------------------------------------------------------

$("#open-example").addEventListener("click", openExample);
$("#files").addEventListener("change", (e) => loadFiles(e.target.files));
$("#submit").addEventListener("click", submit);
$("#cancel").addEventListener("click", async () => {
    if (!state.jobId) return;
    try {
        await cancelJob(state.jobId);
    } catch (e) {
        errors.show(e, null);
    }
});
$("#refresh-jobs").addEventListener("click", refreshJobs);
for (const radio of document.querySelectorAll("input[name=mode]")) {
    radio.addEventListener("change", () => {
        view.setMode(radio.value);
        redraw();
    });
}
window.addEventListener("dragover", (e) => {
    e.preventDefault();
    document.body.classList.add("dragging");
});
window.addEventListener("dragleave", () => document.body.classList.remove("dragging"));
window.addEventListener("drop", (e) => {
    e.preventDefault();
    document.body.classList.remove("dragging");
    loadFiles(e.dataTransfer.files);
});

view.setMode(document.querySelector("input[name=mode]:checked").value);
redraw();
loadExamples();
refreshJobs();
