// The player of a simcli run (simcli --animate). Plain JavaScript, no
// library: the page must open offline, forever, from one file. simcli embeds
// this file at build time and writes the run's data beside it (run-meta,
// run-frames, run-series, run-hits, and run-order with --colour-by psi6;
// formats in apps/simcli/animation.hpp).
"use strict";

(() => {
  const errors = [];
  window.addEventListener("error", (event) => errors.push(String(event.message)));
  const openedAt = performance.now();

  // ---- the run's data ----
  const meta = JSON.parse(document.getElementById("run-meta").textContent);
  const bytesOf = (id) => {
    const element = document.getElementById(id);
    const text = atob(element.textContent.trim());
    element.textContent = ""; // decoded once: the DOM need not keep tens of megabytes of text
    const bytes = new Uint8Array(text.length);
    for (let k = 0; k < text.length; ++k) bytes[k] = text.charCodeAt(k);
    return bytes.buffer;
  };
  const count = meta.particles;
  const frameCount = meta.times.length;
  // Frame-major: x, y, vx, vy per particle, in units of meta.unit (float32
  // holds any box that way: 1e-60 would round to 0, 1e60 overflow).
  const frames = new Float32Array(bytesOf("run-frames"));
  const unit = meta.unit;
  const series = new Float64Array(bytesOf("run-series")); // per frame: particle hits, wall hits, steps, energy
  const hitWords = new Uint32Array(bytesOf("run-hits"));
  const hits = []; // per frame: [index, particle hits, wall hits, ...] since the frame before
  for (let at = 0, f = 0; f < frameCount; ++f) {
    const n = hitWords[at++];
    hits.push(hitWords.subarray(at, at + 3 * n));
    at += 3 * n;
  }
  // --colour-by psi6: per frame and particle, the local psi6's phase and modulus (bytes).
  const order = meta.colourBy === "psi6" ? new Uint8Array(bytesOf("run-order")) : null;
  // Component k (x, y, vx, vy) of particle i in frame f, in the run's units.
  const frameValue = (f, i, k) => frames[(f * count + i) * 4 + k] * unit;
  const L = meta.box;
  const r = meta.radius;
  const periodic = meta.periodic === true;

  // ---- elements and settings ----
  const $ = (id) => document.getElementById(id);
  const box = $("box");
  const ctx = box.getContext("2d");
  const scrubber = $("scrubber");
  scrubber.max = String(frameCount - 1);
  $("run-title").textContent =
    `${count} particles, L = ${L}, r = ${r}, ${meta.steps} steps, ` +
    (meta.engine === "exact" ? "exact engine" : `step rules${meta.substeps > 1 ? `, ${meta.substeps} substeps` : ""}`) +
    (meta.every !== 1 ? `, one frame every ${meta.every} step${meta.every === 1 ? "" : "s"}` : "");
  const settings = { colour: order ? "psi6" : "speed", trails: "none", showHits: true, showOverlaps: true, chosen: -1, fps: 20 };
  if (order) {
    const option = document.createElement("option");
    option.value = "psi6";
    option.textContent = "by psi6 phase";
    $("colour").prepend(option);
    $("colour").value = "psi6";
    $("psi6-figure").hidden = false;
    $("pressure-figure").hidden = !meta.pressure.some((p) => p !== null);
  }
  let current = 0;
  let playing = null;

  // ---- geometry: world to canvas pixels, y upwards ----
  const margin = 6;
  const scale = (box.width - 2 * margin) / L;
  const px = (x) => margin + x * scale;
  const py = (y) => box.height - margin - y * scale;
  const radiusPx = r * scale;
  const asPoints = count > 20000 || radiusPx < 1;
  const drawRadius = Math.max(radiusPx, 1.5); // tiny disks stay visible
  const dot = count > 50000 ? 2 : 3; // pixels a side of a dot, each on whole pixels
  const dotOffset = Math.floor((dot - 1) / 2);

  // ---- colours ----
  const stops = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]]; // viridis
  const ramp = (t) => {
    const s = Math.min(Math.max(t, 0), 1) * (stops.length - 1);
    const k = Math.min(Math.floor(s), stops.length - 2);
    const a = stops[k], b = stops[k + 1], w = s - k;
    return `rgb(${Math.round(a[0] + (b[0] - a[0]) * w)},${Math.round(a[1] + (b[1] - a[1]) * w)},${Math.round(a[2] + (b[2] - a[2]) * w)})`;
  };
  const buckets = 32;
  const bucketColours = Array.from({ length: buckets }, (_, k) => ramp(k / (buckets - 1)));
  const fixedColour = "rgb(232,89,12)";
  // psi6: a hue round the wheel for the phase (the local lattice's
  // orientation), four brightnesses for the modulus, as simcli's --snapshot.
  const hueColour = (t, value) => {
    const h = (((t % 1) + 1) % 1) * 6, sector = Math.min(Math.floor(h), 5), w = h - sector;
    const up = value * w, down = value * (1 - w);
    const rgb = [[value, up, 0], [down, value, 0], [0, value, up], [0, down, value], [up, 0, value], [value, 0, down]][sector];
    return `rgb(${rgb.map((c) => Math.round(255 * c)).join(",")})`;
  };
  const levels = 4;
  const psiColours = Array.from({ length: buckets * levels }, (_, k) =>
    hueColour(Math.floor(k / levels) / buckets, 0.25 + (0.75 * ((k % levels) + 0.5)) / levels));
  const psiGroupOf = (f, i) => {
    const at = (f * count + i) * 2;
    const hue = Math.round((order[at] / 255) * buckets) % buckets; // the phase is cyclic: bytes 0 and 255 meet
    return hue * levels + Math.min(levels - 1, Math.floor((order[at + 1] / 256) * levels));
  };

  // Collisions so far of each particle at the current frame (kept incrementally).
  const collisionsSoFar = new Float64Array(count);
  let countedTo = 0;
  const countTo = (f) => {
    if (f < countedTo) {
      collisionsSoFar.fill(0);
      countedTo = 0;
    }
    for (; countedTo < f; ++countedTo) {
      const h = hits[countedTo + 1];
      for (let k = 0; k < h.length; k += 3) collisionsSoFar[h[k]] += h[k + 1] + h[k + 2];
    }
  };

  const speedOf = (f, i) => Math.hypot(frameValue(f, i, 2), frameValue(f, i, 3));
  const bucketOf = (f, i) => {
    if (settings.colour === "collisions") {
      return Math.min(buckets - 1, Math.floor((collisionsSoFar[i] / Math.max(meta.countMax, 1)) * (buckets - 1)));
    }
    const span = meta.speedMax - meta.speedMin;
    const t = span > 0 ? (speedOf(f, i) - meta.speedMin) / span : 0.5;
    return Math.min(buckets - 1, Math.max(0, Math.floor(t * (buckets - 1) + 0.5)));
  };

  // ---- overlaps (the step rules allow them), through a grid of 2r cells ----
  const overlapping = new Uint8Array(count);
  const findOverlaps = (f) => {
    overlapping.fill(0);
    if (count > 50000) return -1;
    const side = Math.max(1, Math.min(1024, Math.floor(L / (2 * r))));
    const cell = L / side;
    const heads = new Int32Array(side * side).fill(-1);
    const next = new Int32Array(count);
    const cellOf = (v) => Math.min(side - 1, Math.max(0, Math.floor(v / cell)));
    for (let i = 0; i < count; ++i) {
      const c = cellOf(frameValue(f, i, 1)) * side + cellOf(frameValue(f, i, 0));
      next[i] = heads[c];
      heads[c] = i;
    }
    let pairs = 0;
    const limit = 4 * r * r * (1 - 1e-6);
    for (let i = 0; i < count; ++i) {
      const x = frameValue(f, i, 0), y = frameValue(f, i, 1);
      const cx = cellOf(x), cy = cellOf(y);
      for (let gy = Math.max(cy - 1, 0); gy <= Math.min(cy + 1, side - 1); ++gy) {
        for (let gx = Math.max(cx - 1, 0); gx <= Math.min(cx + 1, side - 1); ++gx) {
          for (let j = heads[gy * side + gx]; j >= 0; j = next[j]) {
            if (j <= i) continue;
            const dx = frameValue(f, j, 0) - x, dy = frameValue(f, j, 1) - y;
            if (dx * dx + dy * dy < limit) {
              overlapping[i] = overlapping[j] = 1;
              ++pairs;
            }
          }
        }
      }
    }
    return pairs;
  };

  // ---- drawing the box ----
  const draw = (f) => {
    countTo(f);
    ctx.fillStyle = "#ffffff";
    ctx.fillRect(0, 0, box.width, box.height);
    ctx.strokeStyle = "#59636e";
    ctx.lineWidth = 1;
    ctx.strokeRect(px(0) - 0.5, py(L) - 0.5, L * scale + 1, L * scale + 1);
    drawTrails(f);
    const byOrder = settings.colour === "psi6";
    const palette = byOrder ? psiColours : bucketColours;
    const groups = Array.from({ length: palette.length }, () => []);
    for (let i = 0; i < count; ++i) groups[settings.colour === "fixed" ? 0 : byOrder ? psiGroupOf(f, i) : bucketOf(f, i)].push(i);
    // In a periodic box a disk (or a ring round it) across an edge shows its
    // part on each side: its images are drawn too, clipped to the box.
    const side = L * scale;
    const imageShifts = (at, low, high, reach) => {
      const shifts = [0];
      if (periodic && at - reach < low) shifts.push(side);
      if (periodic && at + reach > high) shifts.push(-side);
      return shifts;
    };
    const clipToBox = () => {
      ctx.save();
      ctx.beginPath();
      ctx.rect(px(0), py(L), side, side);
      ctx.clip();
    };
    if (periodic) clipToBox();
    groups.forEach((members, b) => {
      if (members.length === 0) return;
      ctx.fillStyle = settings.colour === "fixed" ? fixedColour : palette[b];
      ctx.beginPath();
      for (const i of members) {
        const x0 = px(frameValue(f, i, 0)), y0 = py(frameValue(f, i, 1));
        for (const dx of imageShifts(x0, px(0), px(L), drawRadius)) {
          for (const dy of imageShifts(y0, py(L), py(0), drawRadius)) {
            const x = x0 + dx, y = y0 + dy;
            if (asPoints) {
              ctx.rect(Math.floor(x) - dotOffset, Math.floor(y) - dotOffset, dot, dot);
            } else {
              ctx.moveTo(x + drawRadius, y);
              ctx.arc(x, y, drawRadius, 0, 2 * Math.PI);
            }
          }
        }
      }
      ctx.fill();
    });
    if (periodic) ctx.restore();
    const ring = (i, colour, extra) => {
      const x0 = px(frameValue(f, i, 0)), y0 = py(frameValue(f, i, 1));
      const reach = drawRadius + extra + ctx.lineWidth;
      if (periodic) clipToBox(); // before the path: clipping begins a path of its own
      ctx.strokeStyle = colour;
      ctx.beginPath();
      for (const dx of imageShifts(x0, px(0), px(L), reach)) {
        for (const dy of imageShifts(y0, py(L), py(0), reach)) {
          ctx.moveTo(x0 + dx + drawRadius + extra, y0 + dy);
          ctx.arc(x0 + dx, y0 + dy, drawRadius + extra, 0, 2 * Math.PI);
        }
      }
      ctx.stroke();
      if (periodic) ctx.restore();
    };
    const overlaps = settings.showOverlaps ? findOverlaps(f) : 0;
    if (settings.showOverlaps && overlaps > 0) {
      ctx.lineWidth = 1.5;
      for (let i = 0; i < count; ++i) if (overlapping[i]) ring(i, "#e03131", 0.5);
    }
    if (settings.showHits) {
      // Flash what collided since the frame before: pairs in magenta, walls in blue.
      ctx.lineWidth = 2;
      const h = hits[f];
      for (let k = 0; k < h.length; k += 3) ring(h[k], h[k + 1] > 0 ? "#d6336c" : "#1c7ed6", 3);
    }
    if (settings.chosen >= 0) {
      ctx.lineWidth = 2;
      ring(settings.chosen, "#000000", 5);
    }
    $("step-label").textContent = `frame ${f + 1} of ${frameCount}`;
    $("time-label").textContent = `step ${formatTime(meta.times[f])} of ${meta.steps}`;
    $("overlap-label").textContent = overlaps > 0 ? `${overlaps} overlapping pair${overlaps === 1 ? "" : "s"}` : "";
    scrubber.value = String(f);
    drawPlots(f);
  };
  const formatTime = (t) => (Number.isInteger(t) ? String(t) : t.toFixed(3));

  const drawTrails = (f) => {
    if (settings.trails === "none") return;
    const members = settings.trails === "all" ? [...Array(Math.min(count, 5000)).keys()] : settings.chosen >= 0 ? [settings.chosen] : [];
    const from = Math.max(0, f - 40);
    ctx.strokeStyle = "rgba(89,99,110,0.55)";
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (const i of members) {
      for (let g = from; g <= f; ++g) {
        const x = px(frameValue(g, i, 0)), y = py(frameValue(g, i, 1));
        // A jump longer than half the box on either axis (a fast bounce, or a
        // wrap through a periodic edge) breaks the line: none across the box.
        const jump = (axis) => Math.abs(frameValue(g, i, axis) - frameValue(g - 1, i, axis));
        const far = g > from && (jump(0) > L / 2 || jump(1) > L / 2);
        if (g === from || far) ctx.moveTo(x, y);
        else ctx.lineTo(x, y);
      }
    }
    ctx.stroke();
  };

  // ---- the plots beside the box ----
  const perStep = (f, column) => {
    const steps = series[f * 4 + 2];
    return steps > 0 ? series[f * 4 + column] / steps : 0;
  };
  // A line starts at frame 1 when its values are over the interval since the
  // frame before (`from: 0` for the state's own values: energy, psi6).
  const plotLines = (canvas, lines, f) => {
    const c = canvas.getContext("2d");
    const w = canvas.width, h = canvas.height, left = 58, bottom = 16;
    c.clearRect(0, 0, w, h);
    let low = Infinity, high = -Infinity;
    for (const line of lines) {
      for (let g = line.from ?? 1; g < frameCount; ++g) {
        const v = line.value(g);
        if (Number.isFinite(v)) { low = Math.min(low, v); high = Math.max(high, v); }
      }
    }
    if (!Number.isFinite(low)) { low = 0; high = 1; }
    // At least a millionth of the values' size: an energy kept to rounding
    // (1e-15) draws flat instead of as noise across the whole height.
    const least = 1e-6 * Math.max(Math.abs(low), Math.abs(high));
    if (high - low < least) {
      const middle = (low + high) / 2;
      low = middle - least / 2;
      high = middle + least / 2;
    }
    if (!(high > low)) { low -= 1; high += 1; }
    canvas.dataset.low = String(low);
    canvas.dataset.high = String(high);
    // The fewest digits (four at least, and every digit of the whole part)
    // that tell the two ends apart, with no trailing zeros: a count's ends
    // read "12345" and "0", not "1.235e+4" or "0.00000".
    // Past fifteen digits, more than a double tells, the whole part goes to
    // exponent notation: an energy of 1e96 reads "9.505005e+96".
    const wholeDigits = Math.floor(Math.log10(Math.max(Math.abs(low), Math.abs(high), 1))) + 1;
    let digits = Math.max(4, wholeDigits <= 15 ? wholeDigits : 4);
    while (digits < 17 && high.toPrecision(digits) === low.toPrecision(digits)) ++digits;
    const endText = (v) => String(Number(v.toPrecision(digits)));
    canvas.dataset.lowText = endText(low);
    canvas.dataset.highText = endText(high);
    const x = (g) => left + ((w - left - 4) * (frameCount > 1 ? g / (frameCount - 1) : 0));
    const y = (v) => h - bottom - ((h - bottom - 6) * (v - low)) / (high - low);
    c.strokeStyle = "#d0d7de";
    c.strokeRect(left, 4, w - left - 4, h - bottom - 4);
    c.fillStyle = "#59636e";
    c.font = "10px sans-serif";
    c.fillText(canvas.dataset.highText, 2, 12);
    c.fillText(canvas.dataset.lowText, 2, h - bottom);
    for (const line of lines) {
      c.strokeStyle = line.colour;
      c.beginPath();
      let drawing = false; // an unknown value (NaN) breaks the line
      for (let g = line.from ?? 1; g < frameCount; ++g) {
        const v = line.value(g);
        if (!Number.isFinite(v)) { drawing = false; continue; }
        (drawing ? c.lineTo : c.moveTo).call(c, x(g), y(v));
        drawing = true;
      }
      c.stroke();
    }
    c.strokeStyle = "#000000";
    c.beginPath();
    c.moveTo(x(f), 4);
    c.lineTo(x(f), h - bottom);
    c.stroke();
  };
  const particleColour = "#d6336c", wallColour = "#1c7ed6";
  // Text in a line's colour: the plot's key.
  const keyed = (text, colour) => {
    const span = document.createElement("span");
    span.textContent = text;
    span.style.color = colour;
    return span;
  };
  const drawPlots = (f) => {
    plotLines($("collisions-plot"), [
      { colour: particleColour, value: (g) => perStep(g, 0) },
      { colour: wallColour, value: (g) => perStep(g, 1) },
    ], f);
    const label = $("collisions-label");
    label.replaceChildren();
    if (f > 0) {
      label.append(keyed(`particles ${formatCount(perStep(f, 0))}`, particleColour), ", ",
        keyed(`walls ${formatCount(perStep(f, 1))}`, wallColour));
    }
    label.dataset.particle = String(perStep(f, 0));
    label.dataset.wall = String(perStep(f, 1));
    plotLines($("energy-plot"), [{ colour: "#2b8a3e", from: 0, value: (g) => series[g * 4 + 3] }], f);
    $("energy-label").textContent = `E = ${series[f * 4 + 3].toPrecision(8)}`;
    drawSpeedHistogram(f);
    if (order) {
      plotLines($("psi6-plot"), [{ colour: "#7048e8", from: 0, value: (g) => meta.psi6[g] }], f);
      $("psi6-label").textContent = meta.psi6[f].toFixed(4);
      $("psi6-label").dataset.value = String(meta.psi6[f]);
      const pressureAt = (g) => (meta.pressure[g] === null ? NaN : meta.pressure[g]);
      plotLines($("pressure-plot"), [{ colour: "#e8590c", value: pressureAt }], f);
      $("pressure-label").textContent = Number.isFinite(pressureAt(f)) ? pressureAt(f).toPrecision(6) : "";
      $("pressure-label").dataset.value = String(pressureAt(f));
    }
  };
  const formatCount = (v) => (Number.isInteger(v) ? String(v) : v.toFixed(2));

  const drawSpeedHistogram = (f) => {
    const canvas = $("speed-plot");
    const c = canvas.getContext("2d");
    const w = canvas.width, h = canvas.height, bottom = 16;
    c.clearRect(0, 0, w, h);
    const bins = 30;
    const counts = new Float64Array(bins);
    let sumSq = 0;
    const top = Math.max(meta.speedMax, 1e-300) * 1.05;
    for (let i = 0; i < count; ++i) {
      const v = speedOf(f, i);
      sumSq += v * v;
      counts[Math.min(bins - 1, Math.floor((v / top) * bins))] += 1;
    }
    // 2D Maxwell (Rayleigh) density with the same mean energy: p(v) = v / s^2 exp(-v^2 / 2 s^2), s^2 = <v^2> / 2.
    const s2 = sumSq / count / 2;
    const width = top / bins;
    const expected = (v) => (s2 > 0 ? ((count * width * v) / s2) * Math.exp((-v * v) / (2 * s2)) : 0);
    let high = 1;
    for (let b = 0; b < bins; ++b) high = Math.max(high, counts[b], expected((b + 0.5) * width));
    const bw = (w - 8) / bins;
    c.fillStyle = "#91a7ff";
    for (let b = 0; b < bins; ++b) {
      const bh = ((h - bottom - 4) * counts[b]) / high;
      c.fillRect(4 + b * bw, h - bottom - bh, bw - 1, bh);
    }
    c.strokeStyle = "#c92a2a";
    c.beginPath();
    for (let k = 0; k <= 100; ++k) {
      const v = (top * k) / 100;
      const yy = h - bottom - ((h - bottom - 4) * expected(v)) / high;
      (k === 0 ? c.moveTo : c.lineTo).call(c, 4 + ((w - 8) * k) / 100, yy);
    }
    c.stroke();
    c.fillStyle = "#59636e";
    c.font = "10px sans-serif";
    c.fillText("0", 4, h - 3);
    c.textAlign = "right"; // inside the plot, however long the number
    c.fillText(`speed ${top.toPrecision(3)}`, w - 4, h - 3);
    c.textAlign = "left";
  };

  // ---- legend ----
  const drawLegend = () => {
    const bar = $("legend-bar").getContext("2d");
    for (let k = 0; k < 220; ++k) {
      bar.fillStyle = settings.colour === "fixed" ? fixedColour : settings.colour === "psi6" ? hueColour(k / 220, 1) : ramp(k / 219);
      bar.fillRect(k, 0, 1, 12);
    }
    if (settings.colour === "psi6") {
      $("legend-low").textContent = "0\u00B0";
      $("legend-high").textContent = "60\u00B0";
      $("legend-name").textContent = "local lattice's orientation (phase of psi6 / 6); darker where |psi6| is small";
      return;
    }
    const byCount = settings.colour === "collisions";
    $("legend-low").textContent = settings.colour === "fixed" ? "" : byCount ? "0" : meta.speedMin.toPrecision(3);
    $("legend-high").textContent = settings.colour === "fixed" ? "" : byCount ? String(meta.countMax) : meta.speedMax.toPrecision(3);
    $("legend-name").textContent =
      settings.colour === "fixed" ? "all disks" : byCount ? "collisions so far" : "speed (length per step)";
  };

  // ---- playing ----
  const go = (f) => {
    current = Math.min(Math.max(f, 0), frameCount - 1);
    draw(current);
  };
  const pause = () => {
    if (playing !== null) clearInterval(playing);
    playing = null;
    $("play").innerHTML = "&#x25B6;";
  };
  const play = () => {
    pause();
    if (current >= frameCount - 1) go(0);
    $("play").innerHTML = "&#x275A;&#x275A;";
    playing = setInterval(() => {
      if (current >= frameCount - 1) pause();
      else go(current + 1);
    }, 1000 / settings.fps);
  };
  const toggle = () => (playing === null ? play() : pause());
  const setSpeed = (fps) => {
    settings.fps = fps;
    $("speed").value = String(fps);
    if (playing !== null) play();
  };
  const speeds = [2, 5, 10, 20, 40, 60];

  $("play").addEventListener("click", toggle);
  $("first").addEventListener("click", () => { pause(); go(0); });
  $("last").addEventListener("click", () => { pause(); go(frameCount - 1); });
  $("back").addEventListener("click", () => { pause(); go(current - 1); });
  $("forward").addEventListener("click", () => { pause(); go(current + 1); });
  scrubber.addEventListener("input", () => { pause(); go(Number(scrubber.value)); });
  $("speed").addEventListener("change", () => setSpeed(Number($("speed").value)));
  $("colour").addEventListener("change", () => { settings.colour = $("colour").value; drawLegend(); draw(current); });
  $("trails").addEventListener("change", () => { settings.trails = $("trails").value; draw(current); });
  $("show-hits").addEventListener("change", () => { settings.showHits = $("show-hits").checked; draw(current); });
  $("show-overlaps").addEventListener("change", () => { settings.showOverlaps = $("show-overlaps").checked; draw(current); });
  box.addEventListener("click", (event) => {
    const rect = box.getBoundingClientRect();
    const x = ((event.clientX - rect.left) * (box.width / rect.width) - margin) / scale;
    const y = (box.height - margin - (event.clientY - rect.top) * (box.height / rect.height)) / scale;
    // The nearest disk, or in a periodic box the nearest image of one.
    const apart = (a, b) => {
      const d = Math.abs(a - b);
      return periodic ? Math.min(d, L - d) : d;
    };
    let best = -1, bestDistance = Infinity;
    for (let i = 0; i < count; ++i) {
      const d = Math.hypot(apart(frameValue(current, i, 0), x), apart(frameValue(current, i, 1), y));
      if (d < bestDistance) { best = i; bestDistance = d; }
    }
    settings.chosen = best;
    $("chosen-label").textContent = best >= 0 ? `particle ${best} chosen` : "";
    draw(current);
  });
  document.addEventListener("keydown", (event) => {
    if (event.target instanceof HTMLSelectElement || event.target instanceof HTMLInputElement && event.target.type !== "range") return;
    const cycle = (select) => { select.selectedIndex = (select.selectedIndex + 1) % select.options.length; select.dispatchEvent(new Event("change")); };
    const handled = {
      " ": toggle,
      ArrowRight: () => { pause(); go(current + 1); },
      ArrowLeft: () => { pause(); go(current - 1); },
      Home: () => { pause(); go(0); },
      End: () => { pause(); go(frameCount - 1); },
      "+": () => setSpeed(speeds[Math.min(speeds.indexOf(settings.fps) + 1, speeds.length - 1)]),
      "-": () => setSpeed(speeds[Math.max(speeds.indexOf(settings.fps) - 1, 0)]),
      c: () => cycle($("colour")),
      t: () => cycle($("trails")),
    }[event.key];
    if (handled) {
      event.preventDefault();
      handled();
    }
  });

  drawLegend();
  const start = /#frame=(\d+)/.exec(location.hash);
  go(start ? Number(start[1]) : 0);
  const openMs = performance.now(); // since the page began to load
  const scriptMs = performance.now() - openedAt;

  // ---- self-test, for the browser tests (tests/test_animation.cpp) ----
  // #selftest={"frame":F,"on":[[x,y],...],"off":[[x,y],...]}: draws frame F in
  // one colour and reports the colour at those world points, then drives the
  // controls and reports what they did.
  const probe = /#selftest=(.*)$/.exec(location.hash);
  if (probe) {
    const request = JSON.parse(decodeURIComponent(probe[1]));
    // The pixel that contains the point (a disk at least 1.5 pixels in radius covers it whole).
    const pixelAt = (x, y) => Array.from(ctx.getImageData(Math.floor(px(x)), Math.floor(py(y)), 1, 1).data.slice(0, 3));
    const results = { frames: frameCount, openMs, scriptMs, scale };
    go(request.frame);
    results.overlapLabel = $("overlap-label").textContent; // with the page's own settings
    if (order) {
      // Before anything else changes the colours: the pixel at each point in
      // the psi6 colouring, and the plots' labels at the last frame.
      settings.showHits = false;
      settings.showOverlaps = false;
      go(request.frame);
      results.psi6Colours = request.on.map(([x, y]) => pixelAt(x, y));
      go(frameCount - 1);
      results.psi6Shown = !$("psi6-figure").hidden;
      results.pressureShown = !$("pressure-figure").hidden;
      results.psi6 = Number($("psi6-label").dataset.value);
      results.pressure = Number($("pressure-label").dataset.value);
      results.psi6First = meta.psi6[0];
      results.psi6Plot = [Number($("psi6-plot").dataset.low), Number($("psi6-plot").dataset.high)];
      results.energy = series[3];
      results.energyPlot = [Number($("energy-plot").dataset.low), Number($("energy-plot").dataset.high)];
      results.energyPlotText = [$("energy-plot").dataset.lowText, $("energy-plot").dataset.highText];
    }
    settings.colour = "fixed";
    settings.showHits = false;
    settings.showOverlaps = false;
    settings.trails = request.trails || "none";
    go(request.frame);
    results.on = request.on.map(([x, y]) => pixelAt(x, y));
    results.off = request.off.map(([x, y]) => pixelAt(x, y));
    results.shownFrame = current;
    if (request.click) {
      // A click on the world point, through the box's drawn size.
      const rect = box.getBoundingClientRect();
      box.dispatchEvent(new MouseEvent("click", {
        clientX: rect.left + (px(request.click[0]) * rect.width) / box.width,
        clientY: rect.top + (py(request.click[1]) * rect.height) / box.height,
      }));
      results.chosen = settings.chosen;
      results.clickedOn = (request.clickedOn || []).map(([x, y]) => pixelAt(x, y));
    }
    const boxShown = box.getBoundingClientRect();
    results.layout = { windowWidth: window.innerWidth, pageWidth: document.documentElement.scrollWidth,
      boxWidth: boxShown.width, boxHeight: boxShown.height };
    scrubber.value = String(request.scrubTo);
    scrubber.dispatchEvent(new Event("input"));
    results.afterScrub = current;
    results.scrubbedOn = (request.scrubOn || []).map(([x, y]) => pixelAt(x, y));
    document.dispatchEvent(new KeyboardEvent("keydown", { key: "ArrowRight" }));
    results.afterRight = current;
    document.dispatchEvent(new KeyboardEvent("keydown", { key: "ArrowLeft" }));
    results.afterLeft = current;
    results.collisions = [];
    const drawingStarted = performance.now();
    let drawn = 0;
    for (let f = 1; f < frameCount && f <= 200; ++f, ++drawn) {
      go(f);
      results.collisions.push([Number($("collisions-label").dataset.particle), Number($("collisions-label").dataset.wall)]);
    }
    // The collisions plot's key: each count in its line's colour.
    results.collisionsKey = Array.from($("collisions-label").children).map((span) => [span.textContent, span.style.color]);
    const collisionsPlot = $("collisions-plot").dataset;
    results.collisionsPlot = [Number(collisionsPlot.low), Number(collisionsPlot.high)];
    results.collisionsPlotText = [collisionsPlot.lowText, collisionsPlot.highText];
    results.drawMs = drawn > 0 ? (performance.now() - drawingStarted) / drawn : 0; // one frame, box and plots
    go(0);
    play();
    setTimeout(() => {
      results.afterPlay = current;
      pause();
      results.errors = errors;
      results.resources = performance.getEntriesByType("resource").length;
      const out = $("selftest");
      out.textContent = JSON.stringify(results);
      out.hidden = false;
    }, 1000);
  }
})();
