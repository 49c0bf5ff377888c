// `cmake --install` puts the viewer beside the daemon, and the installed radiantd finds it with
// no --web-root: PREFIX/bin/radiantd serves PREFIX/share/radiant/web at /.
import { test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { startDaemon } from "../e2e/support.js";

test("the installed daemon serves the installed viewer", async () => {
    const build = process.env.RADIANT_BUILD_DIR;
    assert.ok(build, "RADIANT_BUILD_DIR names the build tree");
    const prefix = mkdtempSync(join(tmpdir(), "radiant-install-"));
    try {
        execFileSync(process.env.CMAKE ?? "cmake", ["--install", build, "--prefix", prefix], {
            stdio: "pipe",
        });
        const daemon = await startDaemon([], join(prefix, "bin", "radiantd"));
        try {
            const page = await fetch(daemon.url);
            assert.equal(page.status, 200);
            assert.equal(page.headers.get("content-type"), "text/html; charset=utf-8");
            const html = await page.text();
            assert.match(html, /<title>Radiant viewer<\/title>/);
            const script = /src="\.\/(assets\/[^"]+\.js)"/.exec(html);
            assert.ok(script, "the page loads its script");
            const js = await fetch(new URL(script[1], daemon.url));
            assert.equal(js.status, 200);
            assert.equal(js.headers.get("content-type"), "text/javascript; charset=utf-8");
            const examples = await (await fetch(new URL("examples/index.json", daemon.url))).json();
            assert.ok(examples.some((e) => e.path === "furnished-office/furnished-office.json"));
            const ies = await fetch(new URL("examples/furnished-office/downlight.ies", daemon.url));
            assert.match(await ies.text(), /^IESNA/);
        } finally {
            await daemon.stop();
        }
    } finally {
        rmSync(prefix, { recursive: true, force: true });
    }
});
