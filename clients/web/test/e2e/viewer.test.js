// The viewer in Debian's Chromium against a real radiantd: scenes dropped and opened, jobs
// followed to the end, and screenshots whose pixels show the room, the lamp's bright spot, the
// legend and an error at its pointer.
import { after, before, test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { formatValue, niceCeiling } from "../../src/colour_scale.js";
import { decodePng } from "./png.js";
import { launchBrowser, screenshot, startDaemon } from "./support.js";

const EXAMPLES = new URL("../../../../proto/examples/", import.meta.url).pathname;
/// The view's background (#1d2229, room_view.js).
const BACKGROUND = [0x1d, 0x22, 0x29];
const LAMP = [1, 1, 2.8];

/// A 4 × 4 × 3 m room with one downlight off-centre, over a 7 × 7 work-plane grid.
function lampRoom(name, settings = {}) {
    return {
        format: "radiant-scene/1",
        name,
        materials: { wall: { reflectance: 0.5 } },
        surfaces: [
            {
                name: "room",
                material: "wall",
                box: { min: [0, 0, 0], max: [4, 4, 3], facing: "in" },
            },
        ],
        luminaires: [
            {
                name: "downlight",
                position: LAMP,
                flux: 3000,
                distribution: "lambertian",
                aim: [0, 0, -1],
            },
        ],
        sensors: [
            {
                name: "workplane",
                normal: [0, 0, 1],
                grid: { origin: [0.25, 0.25, 0.8], u: [3.5, 0, 0], v: [0, 3.5, 0], nu: 7, nv: 7 },
            },
        ],
        settings: { tolerance: 0.02, ...settings },
    };
}

let daemon;
let chromium;
let page;

before(async () => {
    daemon = await startDaemon();
    chromium = await launchBrowser();
    page = await chromium.context.newPage();
    page.on("pageerror", (e) => assert.fail(`page error: ${e.message}`));
    await page.goto(daemon.url);
});

after(async () => {
    await chromium?.close();
    await daemon?.stop();
});

/// Drops files on the page as a person drags them from a file manager.
async function drop(files) {
    await page.evaluate((list) => {
        const transfer = new DataTransfer();
        for (const f of list) transfer.items.add(new File([f.text], f.name));
        window.dispatchEvent(
            new DragEvent("drop", { dataTransfer: transfer, bubbles: true, cancelable: true }),
        );
    }, files);
}

/// Drops `scene` as a file and waits until the viewer has loaded it (the summary names it).
async function dropScene(scene, text = JSON.stringify(scene)) {
    await drop([{ name: `${scene.name}.json`, text }]);
    await page.waitForFunction(
        (name) => document.querySelector("#scene-summary").textContent.startsWith(`${name}:`),
        scene.name,
    );
}

async function submitAndWait(timeout = 60000) {
    await page.waitForFunction(() => !document.querySelector("#submit").disabled);
    const before = await page.evaluate(() => window.radiantViewer.state.jobId);
    await page.click("#submit");
    await page.waitForFunction((old) => window.radiantViewer.state.jobId !== old, before);
    await page.waitForFunction(() => window.radiantViewer.state.resultStatus !== null, null, {
        timeout,
    });
    await page.waitForTimeout(200); // the last frame
    return page.evaluate(() => structuredClone(window.radiantViewer.state));
}

const serviceJson = async (path) => (await fetch(new URL(path, daemon.url))).json();

async function waitForStatus(jobId, status) {
    for (let i = 0; i < 600; ++i) {
        if ((await serviceJson(`v1/jobs/${jobId}`)).status === status) return;
        await new Promise((resolve) => setTimeout(resolve, 50));
    }
    assert.fail(`job ${jobId} never became ${status}`);
}

/// Mean [r, g, b] of the 9 × 9 pixels around the screen point of scene point p.
async function colourAt(png, p) {
    const { x, y } = await page.evaluate((q) => window.radiantViewer.project(q), p);
    const box = await page.locator("#room").boundingBox();
    const sum = [0, 0, 0];
    for (let dy = -4; dy <= 4; ++dy) {
        for (let dx = -4; dx <= 4; ++dx) {
            png.pixel(box.x + x + dx, box.y + y + dy).forEach((c, k) => (sum[k] += c / 81));
        }
    }
    return sum;
}

const brightness = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;

test("a dropped room converges: the room is drawn and the floor under its lamp is brightest", async () => {
    await dropScene(lampRoom("lamp-room"));
    const state = await submitAndWait();
    assert.equal(state.status, "done");
    assert.equal(state.resultStatus, "converged");
    assert.ok(state.meshVersions.length >= 1);
    const png = decodePng(await screenshot(page, "lamp-room-luminance"));

    // The room: most of the view is not background, and it is shaded, not one flat colour.
    const box = await page.locator("#room").boundingBox();
    let drawn = 0;
    const levels = new Set();
    let samples = 0;
    for (let y = box.y + 10; y < box.y + box.height - 10; y += 8) {
        for (let x = box.x + 10; x < box.x + box.width - 10; x += 8) {
            const c = png.pixel(x, y);
            ++samples;
            if (c.some((v, k) => Math.abs(v - BACKGROUND[k]) > 6)) {
                ++drawn;
                levels.add(Math.round(brightness(c) / 8));
            }
        }
    }
    assert.ok(drawn / samples > 0.3, `the room covers ${drawn}/${samples} samples`);
    assert.ok(levels.size > 8, `only ${levels.size} brightness levels`);

    // The floor under the lamp is brighter than the floor at the other three corners.
    const under = brightness(await colourAt(png, [LAMP[0], LAMP[1], 0]));
    for (const corner of [
        [3, 3, 0],
        [3, 1, 0],
        [1, 3, 0],
    ]) {
        const other = brightness(await colourAt(png, corner));
        assert.ok(
            under > other * 1.15,
            `floor under the lamp ${under.toFixed(0)} vs ${corner}: ${other.toFixed(0)}`,
        );
    }
    // The luminance legend.
    assert.equal(await page.locator("#legend").getAttribute("data-kind"), "luminance");
    assert.match(await page.locator(".legend-title").textContent(), /cd\/m²/);
});

test("false colour lux: a blue-to-red legend, the lamp's tile hottest, the result's table", async () => {
    await page.check("input[value=lux]");
    await page.waitForTimeout(200);
    const png = decodePng(await screenshot(page, "lamp-room-lux"));
    const { jobId } = await page.evaluate(() => window.radiantViewer.state);
    const result = await serviceJson(`v1/jobs/${jobId}/result`);
    const [workplane] = result.sensors;

    // The legend: its bar is red at the top, green in the middle, blue at the bottom.
    const bar = await page.locator("#legend canvas").boundingBox();
    const x = bar.x + bar.width / 2;
    const [rt, gt, bt] = png.pixel(x, bar.y + 4);
    const [rm, gm, bm] = png.pixel(x, bar.y + bar.height / 2);
    const [rb, gb, bb] = png.pixel(x, bar.y + bar.height - 4);
    assert.ok(rt > gt + 60 && rt > bt + 60, `top ${[rt, gt, bt]}`);
    assert.ok(gm > rm + 40 && gm > bm + 40, `middle ${[rm, gm, bm]}`);
    assert.ok(bb > rb + 60 && bb > gb, `bottom ${[rb, gb, bb]}`);
    assert.match(await page.locator(".legend-title").textContent(), /lux/);
    const ticks = await page.locator(".legend-ticks span").allTextContents();
    assert.equal(ticks[0], formatValue(niceCeiling(workplane.max)));
    assert.equal(ticks.at(-1), "0");

    // The work plane's tile under the lamp is redder than the one in the far corner.
    const redness = ([r, , b]) => r - b;
    const hot = await colourAt(png, [1.0, 1.0, 0.81]);
    const cold = await colourAt(png, [3.5, 3.5, 0.81]);
    assert.ok(redness(hot) > redness(cold) + 50, `under the lamp ${hot}, far corner ${cold}`);

    // The table shows the result's numbers.
    const row = page.locator('#sensor-table tr[data-sensor="workplane"]');
    assert.equal(await row.locator(".average").textContent(), formatValue(workplane.average));
    assert.equal(await row.locator(".min").textContent(), formatValue(workplane.min));
    assert.equal(await row.locator(".u0").textContent(), workplane.u0.toFixed(2));
    await page.check("input[value=luminance]");
});

test("mesh versions: a hierarchical solve's refined meshes are followed to the final one", async () => {
    // The service keeps only a job's latest mesh and publishes a snapshot at most every half
    // second: the viewer sees the refinements only of a solve that lasts a few seconds (tolerance
    // 0.005: about 2 s), and only if it follows the job before the solve starts. So the one
    // worker is kept busy until the viewer's job is queued and followed.
    const blocker = await fetch(new URL("v1/jobs", daemon.url), {
        method: "POST",
        headers: { "Content-Type": "application/json" },
        body: JSON.stringify(
            lampRoom("blocker", { method: "monte-carlo", tolerance: 1e-6, max_seconds: 120 }),
        ),
    });
    assert.equal(blocker.status, 202);
    const blockerId = (await blocker.json()).id;
    await waitForStatus(blockerId, "running");
    await dropScene(
        lampRoom("lamp-room-hierarchical", { method: "hierarchical", tolerance: 0.005 }),
    );
    await page.waitForFunction(() => !document.querySelector("#submit").disabled);
    await page.click("#submit");
    await page.waitForFunction(() => {
        const { status, following } = window.radiantViewer.state;
        return status === "queued" && following;
    });
    await fetch(new URL(`v1/jobs/${blockerId}`, daemon.url), { method: "DELETE" });
    await page.waitForFunction(() => window.radiantViewer.state.resultStatus !== null, null, {
        timeout: 120000,
    });
    await page.waitForTimeout(200); // the last frame
    const state = await page.evaluate(() => structuredClone(window.radiantViewer.state));
    assert.ok(new Set(state.meshVersions).size >= 2, `mesh versions ${state.meshVersions}`);
    const final = await serviceJson(`v1/jobs/${state.jobId}/result?include=mesh`);
    assert.equal(state.vertices, final.mesh.vertices.length);
    assert.equal(state.meshVersions.at(-1), Math.max(...state.meshVersions));
});

test("the furnished office, dropped with its OBJ, MTL and IES files, converges with its table", async () => {
    const folder = join(EXAMPLES, "furnished-office");
    await drop(
        ["furnished-office.json", "furniture.obj", "furniture.mtl", "downlight.ies"].map(
            (name) => ({
                name,
                text: readFileSync(join(folder, name), "utf8"),
            }),
        ),
    );
    await page.waitForFunction(() =>
        document.querySelector("#scene-summary").textContent.includes("files inlined"),
    );
    const state = await submitAndWait();
    assert.equal(state.resultStatus, "converged");
    const result = await serviceJson(`v1/jobs/${state.jobId}/result`);
    const plane = result.sensors[0];
    const row = page.locator(`#sensor-table tr[data-sensor="${plane.name}"]`);
    assert.equal(await row.locator(".average").textContent(), formatValue(plane.average));
    await page.check("input[value=lux]");
    await page.waitForTimeout(200);
    const png = decodePng(await screenshot(page, "furnished-office"));
    // The work plane's false colours are there: a good share of the view is saturated colour.
    const box = await page.locator("#room").boundingBox();
    let coloured = 0;
    let samples = 0;
    for (let y = box.y; y < box.y + box.height; y += 8) {
        for (let x = box.x; x < box.x + box.width * 0.8; x += 8) {
            const c = png.pixel(x, y);
            ++samples;
            if (Math.max(...c) - Math.min(...c) > 80) ++coloured;
        }
    }
    assert.ok(coloured / samples > 0.1, `false colour on ${coloured}/${samples} samples`);
    await page.check("input[value=luminance]");
});

test("a refused scene is shown at its JSON pointer", async () => {
    const bad = lampRoom("bad-room");
    bad.materials.wall.reflectance = 1.5;
    await dropScene(bad, JSON.stringify(bad, null, 2));
    await page.click("#submit");
    const problem = page.locator('#errors .problem[data-pointer="/materials/wall/reflectance"]');
    await problem.waitFor();
    assert.match(await problem.locator(".message").textContent(), /reflectance/);
    const line = problem.locator(".at-pointer");
    assert.equal(await line.count(), 1);
    assert.match(await line.textContent(), /"reflectance": 1\.5/);
    const png = decodePng(await screenshot(page, "refused-scene"));
    // The highlighted line is drawn in the highlight colour (#ffc9c9) beside its text.
    const where = await line.boundingBox();
    const [r, g, b] = png.pixel(where.x + where.width - 6, where.y + where.height / 2);
    assert.ok(
        r > 240 && Math.abs(g - 0xc9) < 12 && Math.abs(b - 0xc9) < 12,
        `highlight ${[r, g, b]}`,
    );
});

test("a file the scene names but that was not dropped is an error at its reference", async () => {
    const scene = lampRoom("room-with-chair");
    scene.surfaces.push({ name: "chair", material: "wall", obj_file: "chair.obj" });
    await drop([{ name: "with-chair.json", text: JSON.stringify(scene) }]);
    const problem = page.locator('#errors .problem[data-pointer="/surfaces/1/obj_file"]');
    await problem.waitFor();
    assert.match(await problem.locator(".message").textContent(), /cannot read chair\.obj/);
    assert.match(await problem.locator(".at-pointer").textContent(), /"obj_file": "chair\.obj"/);
    assert.equal(await page.locator("#submit").isDisabled(), true);
});

test("an example is opened, cancelled while it runs, and past jobs reopen", async () => {
    await page.selectOption("#examples", "cornell-box.json");
    await page.click("#open-example");
    await page.waitForFunction(() =>
        document.querySelector("#scene-summary").textContent.startsWith("cornell"),
    );
    await page.click("#submit");
    // Running, with a first picture drawn.
    await page.waitForFunction(
        () =>
            window.radiantViewer.state.status === "running" &&
            window.radiantViewer.state.snapshotVersion !== null,
        null,
        { timeout: 60000 },
    );
    assert.ok(Number(await page.locator("#progress").getAttribute("data-error-estimate")) >= 0);
    await page.click("#cancel");
    await page.waitForFunction(() => window.radiantViewer.state.status === "cancelled", null, {
        timeout: 30000,
    });
    const cancelledId = await page.evaluate(() => window.radiantViewer.state.jobId);

    // Every job of this session is listed, newest first, with its status.
    await page.click("#refresh-jobs");
    await page.waitForFunction(
        (id) => document.querySelector("#jobs button")?.dataset.job === id,
        cancelledId,
    );
    const listed = await page
        .locator("#jobs button")
        .evaluateAll((buttons) => buttons.map((b) => [b.dataset.job, b.dataset.status]));
    const jobs = (await serviceJson("v1/jobs?limit=20")).jobs.map((j) => [j.id, j.status]);
    assert.deepEqual(listed, jobs);
    assert.equal(listed[0][1], "cancelled");

    // Reopening the furnished office draws its final mesh again.
    const office = listed.find(([, status]) => status === "done");
    await page.click(`#jobs button[data-job="${office[0]}"]`);
    await page.waitForFunction(
        (id) =>
            window.radiantViewer.state.jobId === id &&
            window.radiantViewer.state.resultStatus !== null,
        office[0],
    );
    const state = await page.evaluate(() => window.radiantViewer.state);
    assert.ok(state.vertices > 0 && state.snapshotVersion !== null);
});
