// What the end-to-end tests share: a real radiantd on a loopback port with a fresh job store,
// Debian's Chromium driven by playwright-core (never a downloaded browser), and screenshots.
import { spawn } from "node:child_process";
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { createInterface } from "node:readline";
import { chromium } from "playwright-core";

export const RADIANTD =
    process.env.RADIANTD ?? new URL("../../../../build/bin/radiantd", import.meta.url).pathname;
const CHROMIUM = process.env.CHROMIUM ?? "/usr/bin/chromium";
/// Where screenshots go (ctest sets it inside the build tree).
export const SCREENSHOTS =
    process.env.RADIANT_WEB_SCREENSHOTS ?? join(tmpdir(), "radiant-web-screenshots");

/// Starts `binary` (default RADIANTD) on 127.0.0.1 with a new --data; resolves to {url, stop()}.
export async function startDaemon(args = [], binary = RADIANTD) {
    const dir = mkdtempSync(join(tmpdir(), "radiant-web-"));
    const child = spawn(
        binary,
        ["--listen", "127.0.0.1:0", "--data", join(dir, "data"), "--workers", "1", ...args],
        {
            stdio: ["ignore", "pipe", "pipe"],
            // stop() must not wait for a solve to drain after SIGTERM (20 s by default).
            env: { ...process.env, RADIANT_DRAIN_SECONDS: "0" },
        },
    );
    let log = "";
    child.stderr.on("data", (d) => (log += d));
    const line = await new Promise((resolve, reject) => {
        const timer = setTimeout(() => reject(new Error(`radiantd did not start: ${log}`)), 20000);
        child.on("exit", (code) => reject(new Error(`radiantd exited ${code}: ${log}`)));
        createInterface({ input: child.stdout }).once("line", (l) => {
            clearTimeout(timer);
            resolve(l);
        });
    });
    const match = /^listening on (127\.0\.0\.1:\d+)$/.exec(line);
    if (!match) throw new Error(`radiantd said: ${line}`);
    return {
        url: `http://${match[1]}/`,
        log: () => log,
        async stop() {
            child.kill("SIGTERM");
            await new Promise((resolve) =>
                child.exitCode !== null ? resolve() : child.on("exit", resolve),
            );
            rmSync(dir, { recursive: true, force: true });
        },
    };
}

/// Debian's Chromium, headless, in a fresh profile, with nothing that reaches out to the
/// network; resolves to {context, close()} (a Playwright persistent context: the profile is ours).
export async function launchBrowser() {
    const profile = mkdtempSync(join(tmpdir(), "radiant-chromium-"));
    const context = await chromium.launchPersistentContext(profile, {
        executablePath: CHROMIUM,
        headless: true,
        viewport: { width: 1280, height: 800 },
        args: [
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
        ],
    });
    return {
        context,
        async close() {
            await context.close();
            rmSync(profile, { recursive: true, force: true });
        },
    };
}

/// Saves a screenshot under SCREENSHOTS and returns its bytes.
export async function screenshot(page, name) {
    mkdirSync(SCREENSHOTS, { recursive: true });
    const bytes = await page.screenshot();
    writeFileSync(join(SCREENSHOTS, `${name}.png`), bytes);
    return bytes;
}
