// SPDX-License-Identifier: BSD-3-Clause
// Drive Planner Arena (served by 'mhplan arena') in headless Chromium with puppeteer-core and check what a
// user sees: the problem list holds the campaign's experiments, the planner list its planners, and the
// performance and progress plots are drawn for each planner on its own (an mhplan planner and an OMPL one).
//   node arena_check.js URL SCREENSHOT_DIR EXPERIMENT[,EXPERIMENT...] PLANNER[,PLANNER...]
// Exit 0 when every check passes; 1 (with the failed check) otherwise.
'use strict';
const puppeteer = require('puppeteer-core');

const [url, shotDir, experimentArg, plannerArg] = process.argv.slice(2);
const experiments = experimentArg.split(',');
const planners = plannerArg.split(',');
const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
const TIMEOUT = 60000;

function fail(message) {
  throw new Error(message);
}

// The <img> of a Shiny plot output once it holds a PNG that differs from `previous` and is not trivially
// small; a Shiny error shown in place of the plot fails at once with its text.
async function waitForPlot(page, id, previous) {
  const handle = await page.waitForFunction(
    (id, previous) => {
      const out = document.getElementById(id);
      if (!out) return false;
      if (out.classList.contains('shiny-output-error') && !out.classList.contains('recalculating'))
        return {error: out.innerText || 'error'};
      if (out.classList.contains('recalculating')) return false;
      const img = out.querySelector('img');
      if (!img || !img.complete || img.naturalWidth < 200 || img.naturalHeight < 200) return false;
      if (!img.src.startsWith('data:image/png') || img.src === previous) return false;
      return {src: img.src, width: img.naturalWidth, height: img.naturalHeight};
    },
    {timeout: TIMEOUT, polling: 200}, id, previous);
  const r = await handle.jsonValue();
  if (r.error) fail(`${id}: Planner Arena shows an error instead of the plot: ${r.error}`);
  if (process.env.ARENA_DEBUG)
    require('fs').writeFileSync(`${shotDir}/${id}_debug.png`, Buffer.from(r.src.split(',')[1], 'base64'));
  // Something is drawn: ggplot draws the data in colour (one hue per planner), the frame, grid and text in
  // greys. A blank panel (as Planner Arena draws when its x range collapses) has no coloured pixel.
  r.colored = await page.evaluate(async (src) => {
    const img = new Image();
    img.src = src;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.naturalWidth;
    c.height = img.naturalHeight;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4)
      if (Math.max(d[i], d[i + 1], d[i + 2]) - Math.min(d[i], d[i + 1], d[i + 2]) > 40) ++n;
    return n;
  }, r.src);
  if (r.colored < 100) fail(`${id}: the plot shows no data (${r.colored} coloured pixels)`);
  return r;
}

// Select exactly `wanted` in the checkbox group `name` (Shiny's checkboxGroupInput) by clicking.
async function selectOnly(page, name, wanted) {
  const boxes = await page.$$(`input[type=checkbox][name="${name}"]`);
  if (boxes.length === 0) fail(`no checkbox group '${name}'`);
  // Check the wanted box first, then clear the others: the group is never empty in between (with no planner
  // selected, Planner Arena renders "Select some planners" in place of the plot, which a check could read).
  for (const pass of [true, false])
    for (const box of boxes) {
      const [value, checked] = await box.evaluate((b) => [b.value, b.checked]);
      if ((value === wanted) === pass && (value === wanted) !== checked) await box.click();
    }
}

async function checkboxValues(page, name) {
  return page.$$eval(`input[type=checkbox][name="${name}"]`, (bs) => bs.map((b) => [b.value, b.checked]));
}

// The choices of a Shiny selectInput (selectize keeps them in its own object; a plain <select> in options).
async function selectChoices(page, id) {
  await page.waitForFunction((id) => document.getElementById(id) !== null, {timeout: TIMEOUT}, id);
  return page.evaluate((id) => {
    const el = document.getElementById(id);
    if (el.selectize) return Object.keys(el.selectize.options);
    return Array.from(el.options).map((o) => o.value);
  }, id);
}

// One tab: the problem list, the planners, then a plot per planner selected alone.
async function checkTab(page, prefix, plotId) {
  const problems = await selectChoices(page, `${prefix}_problem`);
  for (const e of experiments)
    if (!problems.includes(e)) fail(`${prefix}: the problem list ${JSON.stringify(problems)} lacks ${e}`);
  if (problems.length !== experiments.length)
    fail(`${prefix}: the problem list ${JSON.stringify(problems)} is not the campaign's ${experiments}`);
  await page.waitForSelector(`input[type=checkbox][name="${prefix}_planners"]`, {timeout: TIMEOUT});
  const boxes = await checkboxValues(page, `${prefix}_planners`);
  const names = boxes.map((b) => b[0]);
  for (const p of planners)
    if (!names.includes(p)) fail(`${prefix}: the planner list ${JSON.stringify(names)} lacks ${p}`);
  // The problem parameters are the planning experiments' own (simulations are in their own database).
  await page.waitForFunction((id) => {
    const el = document.getElementById(id);
    return el && el.innerText.includes('world type');
  }, {timeout: TIMEOUT}, `${prefix}_problem_param_select`);
  const params = await page.$eval(`#${prefix}_problem_param_select`, (el) => el.innerText);
  for (const column of ['scenario', 'robot count', 'start jitter', 'controller'])
    if (params.includes(column)) fail(`${prefix}: the problem parameters list the simulation column '${column}'`);
  let plot = await waitForPlot(page, plotId, '');
  console.log(`${prefix}: problems ${JSON.stringify(problems)}; planners ${JSON.stringify(names)}; ` +
              `plot of all: ${plot.width}x${plot.height} px, ${plot.colored} coloured pixels`);
  for (const p of planners) {
    await selectOnly(page, `${prefix}_planners`, p);
    plot = await waitForPlot(page, plotId, plot.src);
    console.log(`${prefix}: plot of ${p} alone: ${plot.width}x${plot.height} px, ${plot.colored} coloured pixels`);
    await page.screenshot({path: `${shotDir}/arena_${prefix}_${p}.png`, fullPage: true});
  }
}

(async () => {
  const browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({width: 1400, height: 1000});
    const t0 = Date.now();
    await page.goto(url, {waitUntil: 'load', timeout: TIMEOUT});
    // The app switches to the performance page when its default database holds experiments.
    await checkTab(page, 'perf', 'perf_plot');
    await page.click('a[data-value="progress"]');
    await checkTab(page, 'prog', 'prog_plot');
    console.log(`browser checks: ${((Date.now() - t0) / 1000).toFixed(1)} s`);
  } finally {
    await browser.close();
  }
})().then(
  () => process.exit(0),
  (e) => {
    console.error(`arena_check: FAILED: ${e.message}`);
    process.exit(1);
  });
