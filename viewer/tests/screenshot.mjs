// Opens a `dreamscene view` page in Debian's headless chromium (driven by playwright-core),
// waits for the page's rendered-frame signal and saves a screenshot.
// Usage: node screenshot.mjs URL OUT.png [WIDTHxHEIGHT]
// Exits non-zero with the page's error, or when no frame was signalled within the time limit.
import { chromium } from "playwright-core";
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

const [url, out, size = "640x480"] = process.argv.slice(2);
if (!url || !out) {
  console.error("usage: node screenshot.mjs URL OUT.png [WIDTHxHEIGHT]");
  process.exit(2);
}
const [width, height] = size.split("x").map(Number);
const profile = mkdtempSync(join(tmpdir(), "dreamscene-chromium-"));
const executablePath = process.env.CHROMIUM || "/usr/bin/chromium";
// A fresh profile directory (the persistent-context form is how playwright takes one).
const browser = await chromium.launchPersistentContext(profile, {
  executablePath,
  viewport: { width, height },
  headless: true,
  args: [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    // WebGL2 on the CPU: Chromium >= 137 refuses SwiftShader WebGL under --disable-gpu unless
    // it is asked for explicitly.
    "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
  ],
});
let code = 0;
const logs = [];
let page;
try {
  page = browser.pages()[0] ?? (await browser.newPage());
  page.on("console", (m) => logs.push(`${m.type()}: ${m.text()}`));
  page.on("pageerror", (e) => logs.push(`pageerror: ${e.message}`));
  // The page may load only from the server under test: anything else is refused and fails the run.
  const origin = new URL(url).origin;
  const external = [];
  await page.route("**/*", (route) => {
    const u = route.request().url();
    if (u.startsWith(origin) || u.startsWith("data:") || u.startsWith("blob:")) return route.continue();
    external.push(u);
    return route.abort();
  });
  await page.goto(url);
  const timeout = Number(process.env.VIEW_TIMEOUT_MS || 90000);
  await page.waitForFunction(
    () => ["rendered", "error"].includes(document.body.dataset.state), null, { timeout });
  const state = await page.evaluate(() => window.dreamscene);
  if (state.error) throw new Error(`page error: ${state.error}`);
  await page.screenshot({ path: out });
  if (external.length) throw new Error(`the page asked for outside URLs: ${external.join(", ")}`);
  console.log(JSON.stringify({ frames: state.framesAfterLoad, screenshot: out }));
} catch (e) {
  console.error(String(e));
  const state = page ? await page.evaluate(() => window.dreamscene).catch(() => null) : null;
  console.error(`page state: ${JSON.stringify(state)}`);
  for (const line of logs.slice(-20)) console.error(`page ${line}`);
  code = 1;
} finally {
  await browser.close();
  rmSync(profile, { recursive: true, force: true });
}
process.exit(code);
