// node take_screenshot.mjs <candela> <out.png>: the picture of candela serve's page in the README
// (docs/images/serve.png): the Cornell box after it has accumulated a while, through the a-trous denoiser, with
// the panel beside it.
import { launchBrowser, startServer, stopServer } from './serve_harness.mjs';

const [candela, output] = process.argv.slice(2);
const server = await startServer(candela, ['cornell-box', '--backend', 'cpu', '--port', '0', '--no-cache']);
const browser = await launchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: 820, height: 440 } });
  await page.goto(server.url);
  await page.locator('#denoiser').selectOption('atrous');
  // Polled from here: the page's Content-Security-Policy forbids the eval that waitForFunction needs.
  for (;;) {
    const h = await page.evaluate(() => window.candela.header);
    if (h && !h.preview && h.samples >= 32 && h.controls.denoiser === 'atrous') break;
    await new Promise((r) => setTimeout(r, 200));
  }
  await page.screenshot({ path: output });
} finally {
  await browser.close();
  await stopServer(server);
}
