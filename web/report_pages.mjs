// The HTML report in a real browser (docs/report.md#tests): loads each page given in headless
// Chromium with the network off and checks that
//   - no console error or uncaught exception is logged,
//   - no request is made other than the page's own file,
//   - every figure (<div class="plot">) was drawn by Plotly: an SVG (or, for the 3D scene, a
//     WebGL canvas) of non-zero size,
//   - a click on the last image entry (pages with images, web/images.js) shows that image in
//     the viewer, with its thumbnail when the page has it,
// and keeps a full-page PNG screenshot beside each page (NAME.png). The browser: headless.mjs.
// Usage: node report_pages.mjs CHROMIUM PAGE.html...   (exit 0 when every page passes)
import { eachPage } from './headless.mjs';

const [executablePath, ...pages] = process.argv.slice(2);
if (!executablePath || pages.length === 0) {
  console.error('usage: node report_pages.mjs CHROMIUM PAGE.html...');
  process.exit(2);
}
await eachPage(executablePath, pages.map((file) => ({ file })), async (page, { file }, problems) => {
  const plots = await page.evaluate(() => [...document.querySelectorAll('div.plot')].map((div, i) => {
    const drawn = [...div.querySelectorAll('svg.main-svg, canvas')].map((e) => e.getBoundingClientRect())
      .filter((r) => r.width > 0 && r.height > 0);
    const title = div.closest('section')?.querySelector('h2')?.textContent ?? '?';
    const marks = div.querySelectorAll('.scatterlayer .trace, .barlayer .trace, .boxlayer .trace, ' +
                                       '.heatmaplayer image, canvas').length;
    return { i, title, drawn: drawn.length, marks };
  }));
  if (plots.length === 0) problems.push('no figure on the page');
  for (const p of plots) {
    if (p.drawn === 0 || p.marks === 0) problems.push(`figure ${p.i} (${p.title}) not drawn`);
  }
  // An image entry (web/images.js): a click shows that image in the viewer, over its thumbnail
  // when the entry says it has one.
  const entries = await page.locator('tr.image-entry').count();
  if (entries > 0) {
    const entry = page.locator('tr.image-entry').nth(entries - 1);
    const id = await entry.getAttribute('data-image');
    const thumb = (await entry.locator('td').last().textContent()) === 'yes';
    await entry.click();
    await page.waitForTimeout(200);
    const shown = await page.evaluate(() => {
      const div = document.getElementById('image-viewer');
      return {id: div.dataset.image, marks: div.querySelectorAll('.scatterlayer .trace').length,
              images: [...div.querySelectorAll('image')].filter((e) =>
                (e.getAttribute('href') || '').startsWith('data:image/jpeg')).length};
    });
    if (shown.id !== id || shown.marks === 0 || (thumb && shown.images === 0)) {
      problems.push(`image entry ${id}: the viewer shows ${JSON.stringify(shown)}`);
    }
    console.log(`  clicked image ${id}: ${shown.marks} traces, ${shown.images} thumbnail`);
  }
  const png = file.replace(/\.html$/, '') + '.png';
  await page.screenshot({ path: png, fullPage: true });
  return `${file}: ${plots.length} figures, ${problems.length} problems; screenshot ${png}`;
});
