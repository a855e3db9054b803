// Headless Chromium for hecal's report pages (docs/report.md#tests), shared by the browser check
// (report_pages.mjs) and the docs' figures (figure_shots.mjs, scripts/docs-figures.sh): Debian's
// Chromium driven by playwright-core, WebGL on the CPU, and each page opened from its file with
// the network off, every console error, uncaught exception and request other than the file
// itself collected as a problem. eachPage runs a check on a list of pages and exits 0 when no
// page had a problem.
import { chromium } from 'playwright-core';
import { pathToFileURL } from 'node:url';
import path from 'node:path';

export async function launch(executablePath) {
  return chromium.launch({
    executablePath,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           // WebGL (the 3D scene) on the CPU: headless Chromium has no GPU here.
           '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
}

// The page at `file`, loaded offline in a fresh context of `width` × 900 px; close() when done.
export async function openOffline(browser, file, width = 1200) {
  const url = pathToFileURL(path.resolve(file)).href;
  const context = await browser.newContext({ viewport: { width, height: 900 } });
  await context.setOffline(true);
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
  page.on('request', (r) => { if (r.url() !== url) problems.push(`request: ${r.url()}`); });
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForTimeout(300);
  return { page, problems, close: () => context.close() };
}

// Opens each of `items` ({file, ...}) in turn and awaits check(page, item, problems), which
// returns the line to print; prints the problems, closes the browser and exits: 0 when there was
// none, 1 otherwise. `width`: the viewport's.
export async function eachPage(executablePath, items, check, width = 1200) {
  const browser = await launch(executablePath);
  let failures = 0;
  try {
    for (const item of items) {
      const { page, problems, close } = await openOffline(browser, item.file, width);
      console.log(await check(page, item, problems));
      for (const p of problems) console.log(`  ${p}`);
      failures += problems.length;
      await close();
    }
  } finally {
    await browser.close();
  }
  process.exit(failures === 0 ? 0 : 1);
}
