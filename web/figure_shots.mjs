// PNG screenshots of single figures of hecal report pages, for the docs (scripts/docs-figures.sh,
// docs/contour.md#figures): each page is loaded offline in headless Chromium (headless.mjs) and
// the element matching SELECTOR (e.g. #fig3, a <div class="plot"> of web/contour_study.js) is
// written to OUT.png. A page with a console error, an uncaught exception, a network request or no
// such element fails.
// Usage: node figure_shots.mjs CHROMIUM PAGE.html SELECTOR OUT.png [PAGE.html SELECTOR OUT.png]...
import { eachPage } from './headless.mjs';

const [executablePath, ...shots] = process.argv.slice(2);
if (!executablePath || shots.length === 0 || shots.length % 3 !== 0) {
  console.error('usage: node figure_shots.mjs CHROMIUM PAGE.html SELECTOR OUT.png [...]');
  process.exit(2);
}
const items = [];
for (let k = 0; k < shots.length; k += 3) {
  items.push({ file: shots[k], selector: shots[k + 1], png: shots[k + 2] });
}
await eachPage(executablePath, items, async (page, { file, selector, png }, problems) => {
  const element = await page.$(selector);
  if (!element) problems.push(`no element ${selector}`);
  else await element.screenshot({ path: png });
  return `${file} ${selector}: ${problems.length ? 'FAILED' : png}`;
}, 1100);
