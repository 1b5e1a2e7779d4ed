// SPDX-License-Identifier: BSD-3-Clause
// Open an mhplan report (index.html) in headless Chromium with puppeteer-core and check what a reader sees:
// every <img> loaded and not blank, the path figure of the SE(2) experiment says it draws the robot's
// footprints and shows them (pixels of the planners' translucent fills), every table has data rows with no
// empty cell, "nan" or "None", the ranking, per-problem and time-to-quality statistics are there, and the
// machine load is stated.
//   node report_check.js INDEX_HTML SCREENSHOT_DIR
// Exit 0 when every check passes; 1 (with the failed check) otherwise.
'use strict';
const path = require('path');
const puppeteer = require('puppeteer-core');

const [index, shotDir] = process.argv.slice(2);
const chromium = process.env.CHROMIUM || '/usr/bin/chromium';

function fail(message) {
  throw new Error(message);
}

(async () => {
  const browser = await puppeteer.launch({executablePath: chromium, headless: true,
                                          args: ['--no-sandbox', '--allow-file-access-from-files']});
  try {
    const page = await browser.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    page.on('requestfailed', (r) => errors.push('failed to load ' + r.url()));
    await page.setViewport({width: 1280, height: 900});
    await page.goto('file://' + path.resolve(index), {waitUntil: 'load', timeout: 30000});
    if (errors.length) fail(errors.join('; '));

    // Every figure loaded and drawn (coloured pixels: data, not only frame and text).
    const images = await page.$$eval('img', (imgs) => imgs.map((img) => {
      const c = document.createElement('canvas');
      c.width = img.naturalWidth;
      c.height = img.naturalHeight;
      let colored = 0;
      if (img.complete && img.naturalWidth > 0) {
        const g = c.getContext('2d');
        g.drawImage(img, 0, 0);
        const d = g.getImageData(0, 0, c.width, c.height).data;
        for (let i = 0; i < d.length; i += 4)
          if (Math.max(d[i], d[i + 1], d[i + 2]) - Math.min(d[i], d[i + 1], d[i + 2]) > 40) ++colored;
      }
      return {src: img.getAttribute('src'), width: img.naturalWidth, height: img.naturalHeight, colored,
              footprints: img.dataset.footprints};
    }));
    if (images.length < 4) fail(`only ${images.length} figures`);
    for (const img of images) {
      if (img.width < 200 || img.height < 150) fail(`${img.src} did not load (${img.width}x${img.height})`);
      if (img.colored < 200) fail(`${img.src} shows no data (${img.colored} coloured pixels)`);
    }
    for (const prefix of ['box_', 'convergence_', 'paths_', 'success'])
      if (!images.some((i) => i.src.startsWith(prefix))) fail(`no ${prefix} figure`);
    const paths = images.find((i) => i.src.startsWith('paths_se2_narrow_passage'));
    if (!paths) fail('no path figure of se2_narrow_passage');
    if (!(Number(paths.footprints) >= 1)) fail(`the path figure draws no footprint (data-footprints=${paths.footprints})`);
    const text = await page.evaluate(() => document.body.innerText);
    if (!text.includes("The robot's footprint is drawn along each planner's best path"))
      fail('the page does not say the footprints are drawn');

    // Statistics: every table has data rows and no empty, NaN or None cell.
    const tables = await page.$$eval('table', (ts) => ts.map((t) => ({
      header: Array.from(t.querySelectorAll('th')).map((th) => th.innerText),
      rows: Array.from(t.querySelectorAll('tr')).slice(1).map((tr) =>
        Array.from(tr.querySelectorAll('td')).map((td) => td.innerText.trim())),
    })));
    if (tables.length < 3) fail(`only ${tables.length} tables`);
    for (const t of tables) {
      if (t.rows.length === 0) fail(`the table [${t.header.join(' | ')}] has no rows`);
      for (const row of t.rows)
        for (const cell of row)
          if (cell === '' || /\bnan\b|\bNone\b|undefined/i.test(cell))
            fail(`table [${t.header.join(' | ')}]: cell '${cell}' in row [${row.join(' | ')}]`);
    }
    for (const header of ['success rate', 'length median', 'first solution'])
      if (!tables.some((t) => t.header.some((h) => h.includes(header)))) fail(`no table with column '${header}'`);
    for (const planner of ['RRTstar', 'SMA-MEM'])
      if (!tables.some((t) => t.rows.some((r) => r[0] === planner))) fail(`no table row of ${planner}`);
    if (!/Machine load recorded by the campaign: the planners had \d+ % of a core/.test(text))
      fail('the machine load is not stated');
    if (!text.includes('gaps are to the best found cost')) fail('the ranking does not name its reference');
    await page.screenshot({path: path.join(shotDir, 'report.png'), fullPage: true});
    console.log(`report: ${images.length} figures, ${tables.length} tables, path figure with ` +
                `${paths.footprints} footprint path(s)`);
  } finally {
    await browser.close();
  }
})().catch((e) => {
  console.error('FAILED: ' + e.message);
  process.exit(1);
});
