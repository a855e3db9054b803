// The HTML report in a real browser (docs/report.md#tests): loads each page given in headless
// Chromium with the network off and checks that
//   - no console error or uncaught exception is logged,
//   - no request is made other than the page's own file,
//   - every figure (<div class="plot">) was drawn by Plotly: an SVG (or, for the 3D scene, a
//     WebGL canvas) of non-zero size,
// and keeps a full-page PNG screenshot beside each page (NAME.png).
// Usage: node report_pages.mjs CHROMIUM PAGE.html...   (exit 0 when every page passes)
import { chromium } from 'playwright-core';
import { pathToFileURL } from 'node:url';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const [executablePath, ...pages] = process.argv.slice(2);
if (!executablePath || pages.length === 0) {
  console.error('usage: node report_pages.mjs CHROMIUM PAGE.html...');
  process.exit(2);
}
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'hecal-report-chromium-'));
const browser = await chromium.launch({
  executablePath,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync',
         // WebGL (the 3D scene) on the CPU: headless Chromium has no GPU here.
         '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
let failures = 0;
try {
  for (const page_path of pages) {
    const url = pathToFileURL(path.resolve(page_path)).href;
    const context = await browser.newContext({ viewport: { width: 1200, height: 900 } });
    await context.setOffline(true);
    const page = await context.newPage();
    const problems = [];
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
    page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
    page.on('request', (r) => { if (r.url() !== url) problems.push(`request: ${r.url()}`); });
    await page.goto(url, { waitUntil: 'load' });
    await page.waitForTimeout(300);
    const plots = await page.evaluate(() => [...document.querySelectorAll('div.plot')].map((div, i) => {
      const drawn = [...div.querySelectorAll('svg.main-svg, canvas')].map((e) => e.getBoundingClientRect())
        .filter((r) => r.width > 0 && r.height > 0);
      const title = div.closest('section')?.querySelector('h2')?.textContent ?? '?';
      const marks = div.querySelectorAll('.scatterlayer .trace, .barlayer .trace, .boxlayer .trace, canvas').length;
      return { i, title, drawn: drawn.length, marks };
    }));
    if (plots.length === 0) problems.push('no figure on the page');
    for (const p of plots) {
      if (p.drawn === 0 || p.marks === 0) problems.push(`figure ${p.i} (${p.title}) not drawn`);
    }
    const png = page_path.replace(/\.html$/, '') + '.png';
    await page.screenshot({ path: png, fullPage: true });
    console.log(`${page_path}: ${plots.length} figures, ${problems.length} problems; screenshot ${png}`);
    for (const p of problems) console.log(`  ${p}`);
    failures += problems.length;
    await context.close();
  }
} finally {
  await browser.close();
  fs.rmSync(profile, { recursive: true, force: true });
}
process.exit(failures === 0 ? 0 : 1);
