// A Web Worker of the playground (a module worker, started by js/raylab.js): its own .NET runtime, loaded from the
// site's _framework/dotnet.js (the same files as the page's, from the browser's cache), renders bands of rows through
// RayLab (Lab/WorkerRows.cs) and posts each band back.
//
// The worker sets onmessage only once the runtime is up: dotnet.js takes a worker whose onmessage is already set for
// one of its own threads' workers, and its start then never ends (dotnet/runtime#114918). The page sends nothing before
// the 'ready' message, so no message is lost meanwhile.
import { dotnet } from '../_framework/dotnet.js';

let rows = null;
try {
  const runtime = await dotnet.create();
  const exports = await runtime.getAssemblyExports(runtime.getConfig().mainAssemblyName);
  rows = exports.RayLab.Web.Lab.WorkerRows;
} catch (e) {
  postMessage({ type: 'failed', message: String((e && e.message) || e) });
}

if (rows) {
  // Bands wait here; a cancel (a newer picture) drops those of its job and older ones. Between bands the worker posts
  // itself a message and takes the next band when it comes: messages are handled in order, so a cancel the page sent
  // while a band rendered is handled first. (A timer is not: Chromium ran setTimeout(0) before the page's waiting
  // message, and the queued band of a cancelled picture was rendered.)
  const queue = [];
  let dropUpTo = 0, pumping = false;
  const tick = new MessageChannel();
  const next = () => { pumping = true; tick.port2.postMessage(0); };
  tick.port1.onmessage = () => {
    pumping = false;
    const band = queue.shift();
    if (!band) return;
    if (band.job > dropUpTo) render(band);
    else postMessage({ type: 'dropped', job: band.job });
    if (queue.length > 0) next();
  };
  const render = band => {
    const started = performance.now();
    try {
      const bytes = rows.Render(band.query, band.exact, band.width, band.height, band.first, band.count);
      const [primaryRays, renderMs, kernel] = rows.LastBand();
      const buffer = bytes.byteOffset === 0 && bytes.byteLength === bytes.buffer.byteLength ? bytes.buffer : bytes.slice().buffer;
      // busyMs: the worker's whole time on the band (the library's render, the band's bytes out of .NET, the message).
      const busyMs = performance.now() - started;
      postMessage({ type: 'rows', job: band.job, first: band.first, count: band.count, bytes: buffer, primaryRays, renderMs, kernel, busyMs }, [buffer]);
    } catch (e) {
      postMessage({ type: 'error', job: band.job, first: band.first, count: band.count, message: String((e && e.message) || e) });
    }
  };
  onmessage = e => {
    const m = e.data;
    if (m.type === 'band') {
      queue.push(m);
      if (!pumping) next();
    } else if (m.type === 'cancel') {
      dropUpTo = Math.max(dropUpTo, m.job);
      // Dropped bands are answered, so that the page counts each worker's bands in flight right.
      for (const band of queue.filter(b => b.job <= dropUpTo)) postMessage({ type: 'dropped', job: band.job });
      queue.splice(0, queue.length, ...queue.filter(b => b.job > dropUpTo));
    }
  };
  postMessage({ type: 'ready' });
}
