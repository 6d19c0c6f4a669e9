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

function imageData(ctx, rgb, width, height) {
  const image = ctx.createImageData(width, height);
  const d = image.data;
  for (let i = 0, j = 0, k = 0; i < width * height; i++, j += 3, k += 4) {
    d[k] = rgb[j]; d[k + 1] = rgb[j + 1]; d[k + 2] = rgb[j + 2]; d[k + 3] = 255;
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
