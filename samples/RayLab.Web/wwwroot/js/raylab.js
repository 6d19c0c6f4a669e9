// The page's small JavaScript side: paint RGB24 bytes onto a canvas, and turn pointer input on the canvas
// (mouse drag, wheel, touch drag and pinch, click) into calls to the .NET component.

export function paint(id, rgb, width, height) {
  const ctx = sized(id, width, height);
  if (ctx) ctx.putImageData(imageData(ctx, rgb, width, height), 0, 0);
}

function sized(id, width, height) {
  const canvas = document.getElementById(id);
  if (!canvas) return null;
  if (canvas.width !== width) canvas.width = width;
  if (canvas.height !== height) canvas.height = height;
  return canvas.getContext('2d');
}

// RGB24 to the canvas' RGBA. Where typed arrays are little-endian (every browser's machine in practice), a pixel is one
// 32-bit store, the bytes R, G, B, 255 in memory; else four byte stores.
const littleEndian = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;
function imageData(ctx, rgb, width, height) {
  const image = ctx.createImageData(width, height);
  if (littleEndian) {
    const d = new Uint32Array(image.data.buffer);
    for (let i = 0, j = 0; i < d.length; i++, j += 3) {
      d[i] = 0xff000000 | (rgb[j + 2] << 16) | (rgb[j + 1] << 8) | rgb[j];
    }
  } else {
    const d = image.data;
    for (let i = 0, j = 0, k = 0; i < width * height; i++, j += 3, k += 4) {
      d[k] = rgb[j]; d[k + 1] = rgb[j + 1]; d[k + 2] = rgb[j + 2]; d[k + 3] = 255;
    }
  }
  return image;
}

// A band of rows of the full picture, as a full render finishes it.
export function paintRows(id, rgb, width, firstRow) {
  const canvas = document.getElementById(id);
  if (!canvas || canvas.width !== width) return;
  const ctx = canvas.getContext('2d');
  ctx.putImageData(imageData(ctx, rgb, width, rgb.length / 3 / width), 0, firstRow);
}

// A preview at a reduced size, scaled up (pixelated) over the whole canvas, which keeps the full size.
const offscreen = document.createElement('canvas');
export function paintPreview(id, rgb, width, height, fullWidth, fullHeight) {
  const ctx = sized(id, fullWidth, fullHeight);
  if (!ctx) return;
  offscreen.width = width; offscreen.height = height;
  const small = offscreen.getContext('2d');
  small.putImageData(imageData(small, rgb, width, height), 0, 0);
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(offscreen, 0, 0, fullWidth, fullHeight);
}

// Pointer input. One orbit call at a time: moves that arrive while .NET renders a preview are summed into the next call,
// so the preview rate follows the render speed and nothing queues up.
export function attach(id, component) {
  const canvas = document.getElementById(id);
  const pointers = new Map();
  let pendingDx = 0, pendingDy = 0, pendingZoom = 1, busy = false, moved = 0, endTimer = 0, pinch = 0;

  async function flush() {
    if (busy || (pendingDx === 0 && pendingDy === 0 && pendingZoom === 1)) return;
    busy = true;
    const dx = pendingDx, dy = pendingDy, zoom = pendingZoom;
    pendingDx = 0; pendingDy = 0; pendingZoom = 1;
    try { await component.invokeMethodAsync('Move', dx, dy, zoom); } finally { busy = false; }
    flush();
  }
  function scheduleEnd(delay) {
    clearTimeout(endTimer);
    endTimer = setTimeout(async () => {
      if (busy || pendingDx !== 0 || pendingDy !== 0 || pendingZoom !== 1) { scheduleEnd(30); return; }
      await component.invokeMethodAsync('MoveEnd');
    }, delay);
  }
  function pixelOf(e) {
    const r = canvas.getBoundingClientRect();
    const w = Number(canvas.dataset.width), h = Number(canvas.dataset.height);
    return [Math.floor((e.clientX - r.left) / r.width * w), Math.floor((e.clientY - r.top) / r.height * h)];
  }
  function spread() {
    const p = [...pointers.values()];
    return Math.hypot(p[0].x - p[1].x, p[0].y - p[1].y);
  }

  canvas.addEventListener('pointerdown', e => {
    canvas.setPointerCapture(e.pointerId);
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    if (pointers.size === 1) moved = 0;
    if (pointers.size === 2) pinch = spread();
    e.preventDefault();
  });
  canvas.addEventListener('pointermove', e => {
    const p = pointers.get(e.pointerId);
    if (!p) return;
    const dx = e.clientX - p.x, dy = e.clientY - p.y;
    p.x = e.clientX; p.y = e.clientY;
    if (pointers.size === 2) {
      const s = spread();
      if (pinch > 0 && s > 0) pendingZoom *= pinch / s;
      pinch = s;
    } else {
      pendingDx += dx; pendingDy += dy;
    }
    moved += Math.abs(dx) + Math.abs(dy);
    if (moved > 3) flush();
  });
  const up = e => {
    if (!pointers.has(e.pointerId)) return;
    pointers.delete(e.pointerId);
    if (pointers.size > 0) return;
    if (moved <= 3 && e.type === 'pointerup') {
      const [x, y] = pixelOf(e);
      component.invokeMethodAsync('Pick', x, y);
    } else if (moved > 3) {
      flush();
      scheduleEnd(0);
    }
  };
  canvas.addEventListener('pointerup', up);
  canvas.addEventListener('pointercancel', up);
  canvas.addEventListener('wheel', e => {
    e.preventDefault();
    pendingZoom *= Math.exp(e.deltaY * 0.001);
    flush();
    scheduleEnd(250);
  }, { passive: false });
}

// How long the main thread was blocked: the longest gap between animation frames since the last call (for the figures).
// A call starts the next gap at its own time, so what blocked the page before it (Blazor's start) is not counted.
let longest = 0, last = 0;
function frame(t) { if (last) longest = Math.max(longest, t - last); last = t; requestAnimationFrame(frame); }
requestAnimationFrame(frame);
export function longestFrameGap() { const l = longest; longest = 0; last = performance.now(); return l; }

// Milliseconds since navigation started (the first picture's time).
export function now() { return performance.now(); }

// The first picture, painted band by band onto the loading page before the page's controls start (Lab/FirstPicture.cs):
// view is .NET's memory view of the band's RGB24 bytes.
export function paintFirstRows(view, width, height, firstRow, method) {
  const canvas = document.getElementById('first');
  if (!canvas) return;
  if (canvas.hidden) {
    canvas.width = width; canvas.height = height; canvas.hidden = false;
    const caption = document.getElementById('first-caption');
    if (caption) caption.textContent = document.documentElement.lang === 'pl'
      ? `Obraz: ${method}, ${width}×${height}. Kontrolki za chwilę.`
      : `The picture: ${method}, ${width}×${height}. The controls follow.`;
  }
  paintRows('first', view.slice(), width, firstRow);
}

/** The page's language, the html lang: index.html's script set it from the session's choice, else the browser's. */
export function language() { return document.documentElement.lang; }

/** The language switch: the html lang, the window's title, and the choice kept for the tab's session. */
export function setLanguage(lang, title) {
  document.documentElement.lang = lang;
  document.title = title;
  try { sessionStorage.setItem('raylab-lang', lang); } catch { /* storage off: the choice lasts until a reload */ }
}

// The page's Web Workers (js/worker.js, each with its own .NET runtime; Lab/Workers.cs calls these). A full picture is
// cut into bands of rows; each worker has at most two bands in flight, so it never waits for the page between bands;
// each band goes to whichever worker is free, and the page paints each as it arrives. A band aims at BandMs of a
// worker's time, from the last band's speed of the same method, at most twice the last band's rows, and at most an
// even share of the rows left, so the workers finish together. A worker's band blocks no input, so it is longer than
// the page's own (30 ms): each band costs a worker about a millisecond besides the render (its bytes out of .NET, the
// messages) and the page a copy and a paint; a cancelled picture's band still under way runs to its end (the page
// drops it), so a band stays well under a drag's preview budget.
const BandMs = 50, InFlight = 2, StartTimeoutMs = 60000;
const pool = { workers: [], current: null, late: 0, dropped: 0, last: null, speed: new Map(), wanted: 0 };

// How many workers the page starts: navigator.hardwareConcurrency − 1, at least 1 (the page's own thread paints and
// listens). globalThis.raylabWorkers, when a number, overrides it (0: no workers; the tests and figures set it).
function wantedWorkers() {
  if (typeof globalThis.raylabWorkers === 'number') return Math.max(0, Math.floor(globalThis.raylabWorkers));
  return Math.max(1, (navigator.hardwareConcurrency || 1) - 1);
}

// Starts the workers and resolves once each is up or has failed: { up, wanted, message, ms } (message: the first
// failure's, or 'off' when no workers are wanted).
export function startWorkers() {
  const wanted = wantedWorkers();
  pool.wanted = wanted;
  const started = performance.now();
  if (wanted === 0) return Promise.resolve({ up: 0, wanted, message: 'off', ms: 0 });
  if (typeof Worker !== 'function') return Promise.resolve({ up: 0, wanted, message: 'no Web Workers', ms: 0 });
  return new Promise(resolve => {
    let settled = 0, message = '';
    const settle = () => { if (++settled === wanted) resolve({ up: pool.workers.length, wanted, message, ms: performance.now() - started }); };
    for (let i = 0; i < wanted; i++) {
      let worker;
      try {
        worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
      } catch (e) {
        message ||= String((e && e.message) || e);
        settle();
        continue;
      }
      const fail = text => { clearTimeout(timer); message ||= text; worker.terminate(); settle(); };
      const timer = setTimeout(() => fail(`no answer in ${StartTimeoutMs / 1000} s`), StartTimeoutMs);
      worker.onerror = e => { e.preventDefault(); fail(e.message || 'the worker did not load'); };
      worker.onmessage = e => {
        if (e.data.type === 'failed') { fail(e.data.message); return; }
        if (e.data.type !== 'ready') return;
        clearTimeout(timer);
        const w = { worker, id: i, busy: 0 };
        worker.onmessage = m => received(w, m.data);
        worker.onerror = ev => { ev.preventDefault(); lost(w, ev.message || 'a worker stopped'); };
        pool.workers.push(w);
        settle();
      };
    }
  });
}

// Renders the picture of a state (its query) on the workers as picture number id (one more than the last), painting
// each band onto the view canvas when paint is true. Resolves with { rows, primaryRays, renderMs, kernel, workers,
// bands, pageMs, late, dropped }, or { cancelled } when a newer picture or a move took over, or { failed, message }
// when a worker refused a band or stopped; each with left, the workers up. takeRows then copies the bytes.
export function renderOnWorkers(id, query, exact, width, height, method, paint) {
  if (pool.current) cancelWorkers(pool.current.id);
  const job = {
    id, query, exact, width, height, method: `${method}|${width}|${exact}`, paint,
    next: 0, done: 0, rgb: new Uint8Array(width * height * 3), rays: new Float32Array(width * height),
    primaryRays: 0, renderMs: 0, kernel: 0, bands: new Map(), busy: new Map(), pageMs: 0, started: performance.now(),
  };
  return new Promise(resolve => {
    job.resolve = resolve;
    pool.current = job;
    globalThis.raylabWorkerRows = 0;
    if (pool.workers.length === 0) { end(job, { failed: true, message: 'no workers' }); return; }
    feed();
  });
}

// Cancels picture number id if it is under way: its bands still to come are dropped here, and the workers drop those
// they hold.
export function cancelWorkers(id) {
  const job = pool.current;
  if (!job || job.id !== id) return;
  for (const w of pool.workers) w.worker.postMessage({ type: 'cancel', job: job.id });
  end(job, { cancelled: true });
}

// Copies the last finished picture's RGB24 bytes and its rays per pixel (as bytes) into .NET's memory views.
export function takeRows(rgb, rays) {
  const job = pool.last;
  if (!job) return false;
  rgb.set(job.rgb);
  rays.set(new Uint8Array(job.rays.buffer));
  pool.last = null;
  return true;
}

// Ends the workers (the page is closed).
export function stopWorkers() {
  if (pool.current) cancelWorkers(pool.current.id);
  for (const w of pool.workers) w.worker.terminate();
  pool.workers = [];
}

function end(job, result) {
  if (pool.current === job) pool.current = null;
  globalThis.raylabWorkerRows = 0;
  result.left = pool.workers.length;
  job.resolve(result);
}

function bandRows(job) {
  const left = job.height - job.next;
  const last = pool.speed.get(job.method);
  const aimed = last ? Math.min(Math.floor(BandMs / Math.max(last.msPerRow, 0.01)), 2 * last.rows) : 2;
  return Math.max(1, Math.min(aimed, Math.ceil(left / (InFlight * pool.workers.length)), left));
}

function feed() {
  const job = pool.current;
  if (!job) return;
  // The least busy worker first, so that bands spread over the workers before any gets a second one.
  for (let sent = true; sent && job.next < job.height;) {
    sent = false;
    const w = pool.workers.reduce((a, b) => (b.busy < a.busy ? b : a));
    if (w.busy >= InFlight) break;
    const count = bandRows(job);
    w.worker.postMessage({ type: 'band', job: job.id, query: job.query, exact: job.exact, width: job.width, height: job.height, first: job.next, count });
    w.busy++;
    job.next += count;
    sent = true;
  }
}

function received(w, m) {
  w.busy = Math.max(0, w.busy - 1);
  const job = pool.current;
  if (m.type === 'rows') {
    if (job && m.job === job.id) {
      const t0 = performance.now();
      const pixels = m.count * job.width;
      const bytes = new Uint8Array(m.bytes);
      pool.speed.set(job.method, { msPerRow: m.renderMs / m.count, rows: m.count });
      new Uint8Array(job.rays.buffer).set(bytes.subarray(0, pixels * 4), m.first * job.width * 4);
      const rgb = bytes.subarray(pixels * 4);
      job.rgb.set(rgb, m.first * job.width * 3);
      if (job.paint) paintRows('view', rgb, job.width, m.first);
      job.primaryRays += m.primaryRays;
      job.renderMs += m.renderMs;
      job.kernel = m.kernel;
      job.bands.set(w.id, (job.bands.get(w.id) || 0) + 1);
      job.busy.set(w.id, (job.busy.get(w.id) || 0) + m.busyMs);
      job.done += m.count;
      job.pageMs += performance.now() - t0;
      globalThis.raylabWorkerRows = job.done; // the rows of the picture under way in so far (the tests wait on it)
      if (job.done === job.height) {
        pool.last = job;
        // For the figures: the bands each worker rendered and its whole time on them ("31+29 in 452+447 ms"), and the
        // page's own time on them (copy and paint).
        const ids = [...job.bands.keys()].sort((a, b) => a - b);
        const bands = `${ids.map(i => job.bands.get(i)).join('+')} in ${ids.map(i => job.busy.get(i).toFixed(0)).join('+')} ms`;
        // And the bands of cancelled pictures since the last picture: come back late and dropped here, dropped by the workers.
        end(job, { rows: job.height, primaryRays: job.primaryRays, renderMs: job.renderMs, kernel: job.kernel, workers: job.bands.size, bands, pageMs: job.pageMs, late: pool.late, dropped: pool.dropped });
        pool.late = 0;
        pool.dropped = 0;
        return;
      }
    } else {
      pool.late++;
    }
  } else if (m.type === 'dropped') {
    pool.dropped++;
  } else if (m.type === 'error' && job && m.job === job.id) {
    for (const other of pool.workers) other.worker.postMessage({ type: 'cancel', job: job.id });
    end(job, { failed: true, message: m.message });
    return;
  }

  feed();
}

function lost(w, message) {
  w.worker.terminate();
  pool.workers = pool.workers.filter(x => x !== w);
  if (pool.current) end(pool.current, { failed: true, message });
}
