// Browser test of `segslam view`: serves fixture run folders, opens the page in headless Debian
// chromium through playwright-core, checks that the map loads, that toggling a label and the
// dynamic layer changes what is drawn, that a run without a map says so, and saves a screenshot.
// With --run DIR it only loads that run and saves the screenshot (for the notes).
// Exits 77 (CTest's skip code here) when chromium, playwright-core or the web build is missing.
//
//   node web/test/viewer_browser_test.mjs --cli build/segslam [--work DIR] [--run DIR]
//        [--screenshot FILE] [--chromium /usr/bin/chromium] [--size 1280x800]
import { spawn } from "node:child_process";
import { existsSync, mkdirSync, rmSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { parseArgs } from "node:util";
import { writeFixtureRun } from "./fixture_run.mjs";

const SKIP = 77;
const webRoot = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const { values: args } = parseArgs({
  options: {
    cli: { type: "string" },
    work: { type: "string", default: join(webRoot, "..", "build", "viewer_browser_test") },
    run: { type: "string" },
    screenshot: { type: "string" },
    chromium: { type: "string", default: process.env.SEGSLAM_CHROMIUM ?? "/usr/bin/chromium" },
    "web-dir": { type: "string", default: join(webRoot, "dist") },
    size: { type: "string", default: "1280x800" },
  },
});

function skip(message) {
  console.log(`SKIP: ${message}`);
  process.exit(SKIP);
}

function check(condition, message) {
  if (!condition) throw new Error(`check failed: ${message}`);
  console.log(`ok: ${message}`);
}

// Starts `segslam view` on a free port; resolves with the URL it prints.
function startViewer(runDir) {
  const child = spawn(args.cli, ["view", "--run", runDir, "--port", "0", "--web-dir", args["web-dir"]],
    { stdio: ["ignore", "pipe", "pipe"] });
  let output = "";
  return new Promise((resolveUrl, reject) => {
    const timer = setTimeout(() => reject(new Error(`segslam view printed no URL:\n${output}`)), 60000);
    const onData = (chunk) => {
      output += chunk;
      const match = output.match(/http:\/\/\S+\//);
      if (match) {
        clearTimeout(timer);
        resolveUrl({ child, url: match[0] });
      }
    };
    child.stdout.on("data", onData);
    child.stderr.on("data", onData);
    child.on("exit", (code) => {
      clearTimeout(timer);
      reject(new Error(`segslam view exited with ${code}:\n${output}`));
    });
  });
}

async function openRun(browser, runDir) {
  const { child, url } = await startViewer(runDir);
  const [width, height] = args.size.split("x").map(Number);
  const page = await browser.newPage({ viewport: { width, height } });
  page.on("console", (message) => {
    if (message.type() === "error") console.error(`page console: ${message.text()}`);
  });
  page.on("pageerror", (error) => console.error(`page error: ${error.message}`));
  const stop = () => child.kill("SIGTERM");
  try {
    await page.goto(url, { timeout: 120000 });
    await page.waitForFunction(() => window.segslamViewer?.state.ready, null, { timeout: 120000 });
    const error = await page.evaluate(() => window.segslamViewer.state.error);
    if (error) throw new Error(`the page failed to load the run: ${error}`);
  } catch (error) {
    stop();
    throw error;
  }
  return { page, stop };
}

const stats = (page) => page.evaluate(() => window.segslamViewer.stats());

async function checkMapRun(browser, runDir, screenshot) {
  const { page, stop } = await openRun(browser, runDir);
  try {
    const before = await stats(page);
    check(before.static === 1600 && before.dynamic === 36 && before.objects === 36 + 25 + 16,
      `map loaded: ${before.static} static, ${before.dynamic} dynamic, ${before.objects} object points drawn`);
    check(before.trajectories.estimate === 30 && before.trajectories.ground_truth === 30 &&
      before.trajectories.keyframes === 6, "estimate, ground truth and keyframes drawn");
    check(before.occupancy.voxels === 40 && before.occupancy.grid_cells === 24,
      `occupancy drawn: ${before.occupancy.voxels} occupied voxels, a floor grid of ${before.occupancy.grid_cells} cells`);
    const occupancyRows = await page.$$eval("#layers label", (labels) => labels.map((label) => label.textContent));
    check(occupancyRows.some((row) => row.startsWith("Occupied voxels (40, 0.1 m)")) &&
      occupancyRows.some((row) => row.startsWith("Floor grid (6 x 4, 5 obstacle cells)")),
    `occupancy layers listed: ${JSON.stringify(occupancyRows.slice(-2))}`);
    await page.click('input[data-layer="occupied"]');
    check((await stats(page)).occupancy.voxels === 0, "occupied voxels toggle off");
    await page.click('input[data-layer="occupied"]');
    const rows = await page.$$eval("#objects label", (labels) => labels.map((label) => label.textContent));
    check(rows[0].startsWith("chair (2)") && rows[1].startsWith("chair_1") && rows[1].includes("90 %") &&
      rows[2].startsWith("chair_2") && rows[2].includes("75 %") && rows[3].startsWith("person (1)"),
      `objects listed by label, largest first, with their confidence: ${JSON.stringify(rows)}`);
    await page.click('input[data-label="chair"]');
    const withoutChairs = await stats(page);
    check(withoutChairs.labels.chair === 0 && withoutChairs.labels.person === 16 &&
      withoutChairs.total === before.total - 61, `label toggle: chairs hidden (${before.total} -> ${withoutChairs.total} points)`);
    await page.click('input[data-label="chair"]');
    await page.click('input[data-object="chair_1"]');
    const oneChair = await stats(page);
    const groupState = await page.evaluate(() => document.querySelector('input[data-label="chair"]').indeterminate);
    check(oneChair.labels.chair === 25 && groupState, "instance toggle: one chair left, label box indeterminate");
    await page.click('input[data-object="chair_1"]');
    await page.click('input[data-layer="dynamic"]');
    check((await stats(page)).dynamic === 0, "dynamic layer toggles off");
    await page.click('input[data-layer="dynamic"]');
    check((await stats(page)).total === before.total, "everything back on");
    const status = await page.textContent("#status");
    check(status.includes(`${before.total.toLocaleString("en-US")} points drawn`), `status line: "${status}"`);
    await page.screenshot({ path: screenshot });
    console.log(`screenshot: ${screenshot}`);
  } finally {
    await page.close();
    stop();
  }
}

async function checkRunWithoutMap(browser, runDir) {
  const { page, stop } = await openRun(browser, runDir);
  try {
    const notice = await page.textContent("#notice");
    check(notice.includes("no map in this run"), `run without map: "${notice}"`);
    check((await stats(page)).trajectories.estimate === 30, "trajectories of a run without map drawn");
  } finally {
    await page.close();
    stop();
  }
}

async function screenshotRun(browser, runDir, screenshot) {
  const { page, stop } = await openRun(browser, runDir);
  try {
    // Lets the WebGL canvas settle before the capture.
    await page.waitForTimeout(500);
    await page.screenshot({ path: screenshot });
    console.log(`stats: ${JSON.stringify(await stats(page))}`);
    console.log(`screenshot: ${screenshot}`);
  } finally {
    await page.close();
    stop();
  }
}

async function main() {
  if (!args.cli) throw new Error("--cli PATH_TO_SEGSLAM is required");
  if (!existsSync(args.chromium)) skip(`no chromium at ${args.chromium} (apt-get install chromium)`);
  if (!existsSync(join(args["web-dir"], "index.html"))) {
    skip(`no web build in ${args["web-dir"]} (run scripts/build_web.sh)`);
  }
  let chromium;
  try {
    ({ chromium } = await import("playwright-core"));
  } catch {
    skip("playwright-core is not installed (run scripts/build_web.sh)");
  }
  // Root in a container needs --no-sandbox; WebGL without a GPU runs on SwiftShader.
  const browser = await chromium.launch({
    executablePath: args.chromium,
    headless: true,
    args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist"],
  });
  try {
    if (args.run) {
      await screenshotRun(browser, resolve(args.run), resolve(args.screenshot ?? "screenshot.png"));
      return;
    }
    rmSync(args.work, { recursive: true, force: true });
    mkdirSync(args.work, { recursive: true });
    writeFixtureRun(join(args.work, "run_with_map"), true);
    writeFixtureRun(join(args.work, "run_without_map"), false);
    await checkMapRun(browser, join(args.work, "run_with_map"), resolve(args.screenshot ?? join(args.work, "screenshot.png")));
    await checkRunWithoutMap(browser, join(args.work, "run_without_map"));
  } finally {
    await browser.close();
  }
}

main().catch((error) => {
  console.error(`FAIL: ${error.stack ?? error}`);
  process.exit(1);
});
