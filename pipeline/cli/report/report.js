// Draws the report from the JSON in #report-data: headlines, charts of the Betti numbers of K_t, and
// per run the facts, the summary, and a barcode and a persistence diagram per cell type and degree.
// Hovering a bar or a point shows its birth, death, lifetime and the CC3D ids of the cells that
// formed and killed the class.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("report-data").textContent);
  const NS = "http://www.w3.org/2000/svg";
  const runColours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"];
  const degreeColours = ["#1f77b4", "#d62728", "#2ca02c"];
  const featureNames = [["cluster", "clusters"], ["loop", "loops"], ["cavity", "cavities"]];
  const simplexNames = ["vertex", "edge", "triangle", "tetrahedron", "4-simplex"];
  const tooltip = document.getElementById("tooltip");

  function el(tag, attrs, parent, text) {
    const e = document.createElementNS(NS, tag);
    for (const k in attrs) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  function html(tag, attrs, parent, text) {
    const e = document.createElement(tag);
    for (const k in attrs) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  function fmt(t) { return String(Number(Number(t).toPrecision(6))); }
  function typeTitle(label, name) {
    if (label === "all") return "all cells";
    return "type " + label + (name ? " (" + name + ")" : "");
  }
  function degreeName(run, k) {
    if (k === 2 && run.facts.dimension === 2) return ["space-time bubble", "space-time bubbles"];
    return featureNames[k];
  }
  // The page's other sections (classes3d.js) write with the same words and numbers.
  window.medusaReportText = { html, fmt, typeTitle, degreeName };
  function showTip(evt, text) {
    tooltip.textContent = text;
    tooltip.style.display = "block";
    moveTip(evt);
  }
  function moveTip(evt) {
    const w = tooltip.offsetWidth, h = tooltip.offsetHeight;
    let x = evt.clientX + 14, y = evt.clientY + 14;
    if (x + w > window.innerWidth) x = Math.max(0, evt.clientX - w - 14);
    if (y + h > window.innerHeight) y = Math.max(0, evt.clientY - h - 14);
    tooltip.style.left = x + "px";
    tooltip.style.top = y + "px";
  }
  function hideTip() { tooltip.style.display = "none"; }
  function hover(node, text) {
    node.addEventListener("mouseenter", (e) => showTip(e, text));
    node.addEventListener("mousemove", moveTip);
    node.addEventListener("mouseleave", hideTip);
  }
  function ticks(lo, hi, n) {
    if (!(hi > lo)) return [lo];
    const raw = (hi - lo) / n, mag = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= raw);
    const out = [];
    for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) out.push(Number(v.toPrecision(12)));
    return out;
  }
  // Axes of a plot area: x from x0..x1 (MCS), y from y0..y1.
  // With logY the y axis shows log(1 + y), labelled in y, so that 0 has a place on it.
  function axes(svg, box, xr, yr, xlabel, ylabel, integerY, noYTicks, logY) {
    const [left, top, w, h] = box;
    const sx = (v) => left + ((v - xr[0]) / (xr[1] - xr[0] || 1)) * w;
    const ly = (v) => (logY ? Math.log10(1 + v) : v);
    const sy = (v) => top + h - ((ly(v) - ly(yr[0])) / (ly(yr[1]) - ly(yr[0]) || 1)) * h;
    el("rect", { x: left, y: top, width: w, height: h, fill: "none", stroke: "#999" }, svg);
    for (const t of ticks(xr[0], xr[1], 5)) {
      el("line", { x1: sx(t), x2: sx(t), y1: top + h, y2: top + h + 4, stroke: "#999" }, svg);
      el("text", { x: sx(t), y: top + h + 15, "text-anchor": "middle" }, svg, fmt(t));
    }
    const logTicks = [0, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000].filter((v) => v >= yr[0] && v <= yr[1]);
    for (const t of noYTicks ? [] : logY ? logTicks : ticks(yr[0], yr[1], 4)) {
      if (integerY && t !== Math.round(t)) continue;
      el("line", { x1: left - 4, x2: left, y1: sy(t), y2: sy(t), stroke: "#999" }, svg);
      el("text", { x: left - 6, y: sy(t) + 4, "text-anchor": "end" }, svg, fmt(t));
    }
    if (xlabel) el("text", { x: left + w / 2, y: top + h + 29, "text-anchor": "middle" }, svg, xlabel);
    if (ylabel)
      el("text", { transform: "translate(" + (left - 36) + "," + (top + h / 2) + ") rotate(-90)", "text-anchor": "middle" }, svg, ylabel);
    return [sx, sy];
  }

  // A line chart; series: [{name, colour, xs, ys, dashed}] (null values are left out).
  function lineChart(parent, title, series, ylabel, width, height, xlabel, logY) {
    const svg = el("svg", { class: "chart", width: width, height: height, viewBox: "0 0 " + width + " " + height }, parent);
    el("text", { class: "title", x: 50, y: 16 }, svg, title);
    const xs = series.flatMap((s) => s.xs), ys = series.flatMap((s) => s.ys).filter((y) => y !== null);
    const xr = [Math.min(...xs), Math.max(...xs)], yr = [0, Math.max(logY ? 2 : 1, ...ys)];
    // Legend columns as wide as the longest name (about 6.5 px a character at 11 px).
    const longest = Math.max(...series.map((s) => s.name.length));
    const columns = Math.max(1, Math.min(3, Math.floor((width - 80) / (longest * 6.5 + 30))));
    const rows = Math.ceil(series.length / columns);
    const [sx, sy] = axes(svg, [50, 26, width - 70, height - 70 - 14 * rows], xr, yr, xlabel || "MCS", ylabel, true, false, logY);
    series.forEach((s, i) => {
      let d = "", pen = "M";
      s.xs.forEach((x, j) => {
        if (s.ys[j] === null) { pen = "M"; return; }
        d += pen + sx(x).toFixed(1) + "," + sy(s.ys[j]).toFixed(1);
        pen = "L";
      });
      const dash = s.dashed ? { "stroke-dasharray": "5,3" } : {};
      el("path", Object.assign({ d: d, fill: "none", stroke: s.colour, "stroke-width": 2 }, dash), svg);
      s.xs.forEach((x, j) => {
        if (s.ys[j] === null) return;
        const c = el("circle", { cx: sx(x), cy: sy(s.ys[j]), r: 3, fill: s.colour }, svg);
        hover(c, s.name + "\n" + (xlabel || "MCS") + " " + fmt(x) + ": " + s.ys[j]);
      });
      const lx = 60 + (i % columns) * ((width - 80) / columns), ly = height - 8 - 14 * (rows - 1 - Math.floor(i / columns));
      el("line", Object.assign({ x1: lx, x2: lx + 16, y1: ly - 4, y2: ly - 4, stroke: s.colour, "stroke-width": 3 }, dash), svg);
      el("text", { x: lx + 20, y: ly }, svg, s.name);
    });
    return svg;
  }

  function pairText(run, panel, p) {
    const [birth, death, bcell, dcell, bids, dids] = p;
    const names = degreeName(run, panel.dim);
    const cellWords = (ids) => (ids.length === 2 ? "an " : "a ") + simplexNames[ids.length - 1] + " of CC3D cell" +
      (ids.length === 1 ? " " : "s ") + ids.join(", ");
    const lines = ["H" + panel.dim + " " + names[0] + " · " + typeTitle(panel.label, panel.name) + " · forward filtration",
      "birth: MCS " + fmt(birth) + " (medusa cell " + bcell + ", " + cellWords(bids) + ")"];
    if (death === null) {
      // An essential loop or cavity was never filled; it need not be open at the end (README, Reading the summary).
      lines.push(panel.dim === 0 ? "death: never (an essential class: this cluster never joined an older one)"
        : panel.dim === 2 && run.facts.dimension === 2
          ? "death: never (a bubble of space-time: a hole inside the tissue that closed again, born when it closed; never a cavity at one time)"
          : "death: never (an essential class: never filled by cells; it may have broken open instead)");
      lines.push("lifetime: " + fmt(run.facts.t_end - birth) + " MCS or more (to the end of the run)");
      if (p.length > 6) {
        const what = panel.dim === 2 ? "shell" : "ring";
        lines.push(p[6] === null ? "the contacts of the cells it is listed with were never all present at once: a " + names[0] + " of space-time only"
          : p[6] >= run.facts.t_end ? "the " + what + " of cells it is listed with is whole at the end"
          : "the " + what + " of cells it is listed with broke open at MCS " + fmt(p[6]) + " (solid until then)");
      }
    } else {
      lines.push("death: MCS " + fmt(death) + " (medusa cell " + dcell + ", " + cellWords(dids) + ")");
      lines.push("lifetime: " + fmt(death - birth) + " MCS");
    }
    return lines.join("\n");
  }

  // The H0 panels end a little after the last birth or join (a round value), when that is well before
  // the end of the run: clusters join in the first few hundred MCS. Other degrees, and an H0 panel
  // without a join (one cluster throughout), span the whole run.
  function zoomedEnd(run, panel) {
    const t0 = run.facts.t0, t1 = run.facts.t_end;
    if (panel.dim !== 0 || !panel.pairs.some((p) => p[1] !== null)) return t1;
    let last = t0;
    for (const p of panel.pairs) last = Math.max(last, p[0], p[1] === null ? p[0] : p[1]);
    const target = t0 + Math.max(last - t0, (t1 - t0) / 100) * 1.1;
    const tk = ticks(t0, target, 5), step = tk.length > 1 ? tk[1] - tk[0] : target - t0;
    const end = t0 + Math.ceil((target - t0) / step) * step;
    return end < t0 + 0.7 * (t1 - t0) ? end : t1;
  }

  // Each bar has a row of its own, at least a pixel tall, so a panel of many bars grows taller: the
  // pointer names the bar of the row it is in, when it is within a few pixels of the bar's ends.
  // Hit-testing the bars themselves named whichever overlapping bar was drawn last.
  function barcode(parent, run, panel, ri, pi) {
    const n = panel.pairs.length, width = 400, barH = n > 150 ? 1 : n > 60 ? 2 : 4;
    const height = Math.max(90, n * barH + 56);
    const rowH = (height - 46) / Math.max(1, n), colour = degreeColours[panel.dim];
    const svg = el("svg", { class: "barcode", width: width, height: height, viewBox: "0 0 " + width + " " + height,
      "data-row-height": rowH }, parent);
    const t0 = run.facts.t0, t1 = zoomedEnd(run, panel);
    const zoomed = t1 < run.facts.t_end;
    const [sx] = axes(svg, [20, 8, width - 36, height - 46], [t0, t1], [0, 1],
      zoomed ? "MCS " + fmt(t0) + "–" + fmt(t1) + " of " + fmt(t0) + "–" + fmt(run.facts.t_end) + " (zoomed to the joins)" : "MCS", "", true, true);
    const rects = [], spans = [];
    panel.pairs.forEach((p, j) => {
      const x0 = sx(p[0]), x1 = p[1] === null ? sx(t1) : sx(p[1]);
      // At least 2 px wide, so that a class living a moment can be pointed at.
      const w = Math.max(2, x1 - x0);
      rects.push(el("rect", { class: "bar", x: x0, y: 8 + j * rowH, width: w, height: Math.max(0.8, rowH * 0.8),
        fill: colour, "fill-opacity": p[1] !== null ? 1 : p.length > 6 && p[6] === null ? 0.12 : 0.3, "data-run": ri, "data-panel": pi, "data-pair": j,
        "data-birth-cell": p[2], "data-death-cell": p[3] === null ? "" : p[3] }, svg));
      spans.push([x0, x0 + w]);
      // A never-filled loop or cavity is solid for as long as its ring or shell stayed whole.
      if (p.length > 6 && p[6] !== null && p[6] > p[0])
        el("rect", { class: "bar-whole", x: x0, y: 8 + j * rowH, width: Math.max(1, Math.min(sx(p[6]), x1) - x0),
          height: Math.max(0.8, rowH * 0.8), fill: colour, "pointer-events": "none", "data-pair": j }, svg);
    });
    let pointed = null;
    const point = (j, e) => {
      if (j !== pointed) {
        if (pointed !== null) rects[pointed].classList.remove("pointed");
        if (j !== null) rects[j].classList.add("pointed");
        pointed = j;
      }
      if (j === null) hideTip();
      else showTip(e, pairText(run, panel, panel.pairs[j]));
    };
    svg.addEventListener("mousemove", (e) => {
      // The pointer's pixel is taken at its centre: a row at least a pixel tall holds one such centre.
      const box = svg.getBoundingClientRect();
      const x = (e.clientX + 0.5 - box.left) * (width / box.width), y = (e.clientY + 0.5 - box.top) * (height / box.height);
      const j = Math.floor((y - 8) / rowH);
      point(j >= 0 && j < n && x >= spans[j][0] - 4 && x <= spans[j][1] + 4 ? j : null, e);
    });
    svg.addEventListener("mouseleave", () => point(null));
    return svg;
  }

  function diagram(parent, run, panel, ri, pi) {
    const size = 260, pad = 48;
    const svg = el("svg", { class: "diagram", width: size, height: size, viewBox: "0 0 " + size + " " + size }, parent);
    const t0 = run.facts.t0, t1 = zoomedEnd(run, panel);
    const zoomed = t1 < run.facts.t_end;
    const [sx, sy] = axes(svg, [pad, 18, size - pad - 20, size - pad - 20], [t0, t1], [t0, t1],
      zoomed ? "birth (MCS, zoomed to the joins)" : "birth (MCS)", "death (MCS)", false);
    el("line", { x1: sx(t0), y1: sy(t0), x2: sx(t1), y2: sy(t1), stroke: "#bbb" }, svg);
    el("text", { x: pad - 6, y: 14, "text-anchor": "end" }, svg, "never");
    el("line", { x1: sx(t0), x2: sx(t1), y1: 10, y2: 10, stroke: "#ddd", "stroke-dasharray": "3,3" }, svg);
    const colour = degreeColours[panel.dim];
    panel.pairs.forEach((p, j) => {
      const c = el("circle", { class: "point", cx: sx(p[0]), cy: p[1] === null ? 10 : sy(p[1]), r: 3,
        fill: colour, "fill-opacity": p[1] === null ? 0.3 : 0.6, "data-run": ri, "data-panel": pi, "data-pair": j }, svg);
      hover(c, pairText(run, panel, p));
    });
    return svg;
  }

  // First screen: per run the headline of each type (types first, all cells last).
  function headlines() {
    const cards = document.getElementById("headlines");
    data.runs.forEach((run, ri) => {
      const card = html("div", { class: "run-card", "data-run": ri }, cards);
      const h = html("h3", {}, card, run.name + " ");
      html("span", { class: "muted" }, h, "radius " + run.facts.radius + " · " + run.facts.cc3d_cells + " cells · " +
        run.facts.frames + " frames, MCS " + run.facts.t0 + "–" + run.facts.t_end +
        (run.facts.domain ? " · " + run.facts.domain : ""));
      const sorts = run.verdict.startsWith("sorts");
      const v = html("p", { class: "verdict " + (sorts ? "sorts" : "no-sort"), "data-run": ri }, card);
      html("b", {}, v, run.name + " " + run.verdict.split(":")[0] + ":");
      v.appendChild(document.createTextNode(run.verdict.slice(run.verdict.indexOf(":") + 1)));
      // What reading the input warned of (later frames missing, snapshots left out): the verdict
      // holds for what was read, so it is said beside it.
      for (const w of run.facts.input_warnings || []) {
        const p = html("p", { class: "input-warning", "data-run": ri }, card);
        html("b", {}, p, "Input warning: ");
        p.appendChild(document.createTextNode(w));
      }
      const ul = html("ul", {}, card);
      for (const x of typesFirst(run.headlines)) {
        const li = html("li", { class: "headline" + (x.label === "all" ? " muted" : ""), "data-type": x.label }, ul);
        html("b", {}, li, typeTitle(x.label, x.name) + ": ");
        li.appendChild(document.createTextNode(x.text));
        html("div", { class: "contacts muted" }, li, x.contacts);
      }
      // With several runs the table and statements under the cards say it for all of them at once.
      if ((run.scale || []).length && data.sweeps.filter((w) => w.run >= 0).length === 1) {
        html("div", { class: "scale-head" }, card, "At other radii (radius sweep):");
        const sl = html("ul", {}, card);
        for (const x of run.scale) html("li", { class: "headline scale", "data-type": x.label }, sl, x.text);
      }
    });
    // Clusters of each type over time, all runs in one chart per type.
    const charts = document.getElementById("glance-charts");
    const labels = [];
    // The cell types only: the whole tissue's clusters are in each run's details.
    data.runs.forEach((r) => r.slices.forEach((s) => { if (s.label !== "all" && !labels.includes(s.label)) labels.push(s.label); }));
    labels.sort((a, b) => Number(a) - Number(b));
    for (const label of labels) {
      const series = [];
      let name = "";
      data.runs.forEach((run, ri) => {
        const s = run.slices.find((x) => x.label === label);
        if (!s) return;
        name = s.name;
        series.push({ name: run.name, colour: runColours[ri % runColours.length], xs: run.frame_times, ys: s.b0 });
      });
      lineChart(charts, typeTitle(label, name) + ": clusters of K_t (b0)", series, "clusters", 420, 270);
    }
  }

  // Cell types first, the whole tissue last: the types are what sorts.
  function typesFirst(items) {
    return items.filter((x) => x.label !== "all").concat(items.filter((x) => x.label === "all"));
  }

  function factsTable(parent, run) {
    const f = run.facts, t = html("table", { class: "facts" }, parent);
    const row = (k, v) => { const tr = html("tr", {}, t); html("td", {}, tr, k); html("td", {}, tr, String(v)); };
    row("store", f.store);
    row("cells", f.cc3d_cells + " CC3D cells (" + f.trajectories + " trajectories)");
    row("cell types", f.types.map((x) => x.id + (x.name ? " " + x.name : "") + ": " + x.cells + " cells").join("; "));
    row("frames", f.frames + ", MCS " + f.t0 + " to " + f.t_end);
    row("dimension", f.dimension + (f.dimension === 2 ? " (planar run)" : ""));
    row("radius", f.radius + " lattice units");
    row("medusa cells", f.medusa_cells_per_dimension.map((n, k) => "dim " + k + ": " + n).join(", "));
    row("source", f.source_files.length ? f.source_files.join(", ") : "(not recorded)");
    const warnings = f.input_warnings || [];
    row("input warnings", warnings.length ? warnings.join("; ") : "none");
    row("made by", (f.software_version ? "medusa " + f.software_version : "medusa") + (f.command_line ? ": " + f.command_line : ""));
  }

  function details() {
    const root = document.getElementById("details");
    data.runs.forEach((run, ri) => {
      const sec = html("section", { class: "run", id: "run-" + ri, "data-run": ri }, root);
      html("h2", {}, sec, "Run " + run.name);
      factsTable(sec, run);
      html("h3", {}, sec, "Summary of the forward diagrams (the counts of medusa run's summary; the classes seen longest are in the tables below)");
      html("pre", { class: "summary" }, sec, run.summary);
      html("h3", {}, sec, "Betti numbers of K_t at the frames");
      html("p", { class: "note" }, sec, "K_t is the alpha complex of the cell centres at time t: b0 counts its clusters, " +
        "b1 its loops (rings, tunnels), b2 its cavities (closed shells), for the whole tissue and for each cell type alone.");
      const charts = html("div", { class: "charts" }, sec);
      for (const s of typesFirst(run.slices)) {
        const names = run.facts.dimension === 2 ? ["b0 clusters", "b1 loops"] : ["b0 clusters", "b1 loops", "b2 cavities"];
        lineChart(charts, typeTitle(s.label, s.name), names.map((n, k) => ({ name: n, colour: degreeColours[k], xs: run.frame_times, ys: s["b" + k] })),
          "Betti number", 420, 250);
      }
      html("h3", {}, sec, "Barcodes and persistence diagrams (forward filtration)");
      html("p", { class: "note" }, sec, "One bar per class: it starts when the cluster, loop or cavity appears and ends when it " +
        "joins an older cluster or is filled; pale bars never end (essential classes, drawn to the end of the run). A loop or cavity never " +
        "filled is solid for as long as the ring or shell of cells it is listed with stayed whole (as in the tables below), pale after it " +
        "broke open, and paler throughout when its contacts were never all present at once. Where a panel has more classes than it draws, " +
        "it draws those seen longest in the tissue, and leaves out those never whole at one time unless all of them fit. The H0 (clusters) panels " +
        "show the time up to the last join only, labelled under the axis. Hover a bar or a point for its " +
        "times and the CC3D cells that formed and killed it. Zero-length classes are not drawn.");
      const grid = html("div", { class: "panels" }, sec);
      typesFirst(run.panels).forEach((panel) => {
        const pi = run.panels.indexOf(panel);
        const div = html("div", { class: "panel", "data-run": ri, "data-type": panel.label, "data-dim": panel.dim,
          "data-total": panel.total, "data-drawn": panel.pairs.length }, grid);
        const names = degreeName(run, panel.dim);
        html("div", { class: "caption" }, div, typeTitle(panel.label, panel.name) + " · H" + panel.dim + " " + names[1]);
        html("div", { class: "count" }, div, panel.pairs.length === panel.total ? panel.total + " " + (panel.total === 1 ? names[0] : names[1])
          : "the " + panel.pairs.length + " seen longest of " + panel.total + " " + names[1] +
            (panel.never_whole_left ? " (the other " + panel.never_whole_left + ", never whole at one time, are not drawn)" : ""));
        if (panel.pairs.length === 0) return;
        barcode(div, run, panel, ri, pi);
        diagram(div, run, panel, ri, pi);
      });
    });
  }

  // Per type, the clusters at the first and last frames against the radius, one colour per sweep.
  function sweepCharts() {
    // Beside the clusters over time on the first screen: they answer "at which scale".
    const root = document.getElementById("glance-charts");
    if (!data.sweeps.length) return;
    const labels = [];
    data.sweeps.forEach((w) => w.types.forEach((t) => { if (t.label !== "all" && !labels.includes(t.label)) labels.push(t.label); }));
    for (const label of labels) {
      const series = [];
      data.sweeps.forEach((w, i) => {
        const t = w.types.find((x) => x.label === label);
        if (!t) return;
        // A sweep named like a run has that run's colour.
        const ri = w.run;
        const colour = runColours[(ri >= 0 ? ri : data.runs.length + i) % runColours.length];
        const times = w.times;
        series.push({ name: w.name + " MCS " + fmt(times[times.length - 1]), colour: colour, xs: w.radii, ys: t.last });
        series.push({ name: w.name + " MCS " + fmt(times[0]), colour: colour, xs: w.radii, ys: t.first, dashed: true });
      });
      lineChart(root, "type " + label + ": clusters (b0) against the radius", series.map((x) => Object.assign({}, x, { xs: x.xs.map(Number) })),
        "clusters, log(1 + b0) scale", 420, 270, "radius", true);
    }
  }

  // "At which radius?": the statements comparing the runs, then per type a table of the clusters at
  // the first and the last frame at each swept radius, one row per run.
  function radiusAnswer() {
    const root = document.getElementById("radius-answer");
    const own = data.sweeps.filter((w) => w.run >= 0);
    // The notes are also warnings on stderr, in lower case there; here each is a sentence.
    const sentence = (n) => n.charAt(0).toUpperCase() + n.slice(1) + (n.endsWith(".") ? "" : ".");
    const notes = () => { for (const n of data.scale.notes || []) html("p", { class: "note sweep-note" }, root, sentence(n)); };
    if (!own.length) return notes();
    html("h3", {}, root, own.length > 1 ? "At which radius do the runs differ?" : "At which radius does it show?");
    const computed = own.filter((w) => w.origin.startsWith("computed"));
    const how = html("p", { class: "note sweep-origin" }, root);
    how.textContent = (computed.length ? "Radius sweep computed at report time from the trajectories in the store" + (data.runs.length > 1 ? "s" : "") + " (the same computation as " +
      "medusa sweep), " + data.scale.how + ": radii " + (data.scale.computed_radii || computed[0].radii).join(", ") + ". " : "") +
      own.filter((w) => !w.origin.startsWith("computed")).map((w) => w.name + ": radius sweep " + w.origin + ".").join(" ");
    notes();
    if (data.scale.statements.length) {
      const ul = html("ul", { class: "radius-statements" }, root);
      for (const st of data.scale.statements) {
        const li = html("li", { class: "radius-statement", "data-type": st.label, "data-radii": st.radii.join(",") }, ul);
        // The clause that answers the question in bold.
        st.text.split(/(the runs (?:do not )?differ.*?(?=\. It |$))/).forEach((part, i) => {
          if (i % 2) html("b", {}, li, part);
          else li.appendChild(document.createTextNode(part));
        });
        li.appendChild(document.createTextNode("."));
      }
    }
    const labels = [];
    own.forEach((w) => w.types.forEach((t) => { if (t.label !== "all" && !labels.includes(t.label)) labels.push(t.label); }));
    const grid = html("div", { class: "radius-tables" }, root);
    for (const label of labels) {
      const radii = [];
      own.forEach((w) => w.radii.forEach((r) => { if (!radii.includes(r)) radii.push(r); }));
      radii.sort((a, b) => Number(a) - Number(b));
      const st = data.scale.statements.find((x) => x.label === label);
      const differ = st ? st.radii : [];
      const box = html("div", { class: "radius-table-box" }, grid);
      const first = own.find((w) => w.types.some((t) => t.label === label));
      const name = (first.types.find((t) => t.label === label) || {}).name;
      html("div", { class: "caption" }, box, typeTitle(label, name) + ": clusters at the first → the last frame, per radius");
      const table = html("table", { class: "radius-table", "data-type": label }, box);
      const head = html("tr", {}, table);
      html("th", {}, head, "radius");
      for (const r of radii) html("th", { class: differ.includes(r) ? "differ" : "" }, head, r);
      for (const w of own) {
        const t = w.types.find((x) => x.label === label);
        const tr = html("tr", {}, table);
        html("th", {}, tr, w.name);
        for (const r of radii) {
          const i = w.radii.indexOf(r);
          if (!t || i < 0) { html("td", {}, tr, ""); continue; }
          const a = t.first[i], b = t.last[i];
          const kind = b !== 1 ? "split" : a === 1 ? "one" : "joins";
          html("td", { class: kind, "data-radius": r }, tr, a + " → " + b);
        }
      }
      const key = html("div", { class: "key" }, box);
      html("span", { class: "joins" }, key, "several → one: joins into one cluster during the run");
      html("span", { class: "one" }, key, "one from the start");
      html("span", { class: "split" }, key, "several at the end");
      if (differ.length) html("span", { class: "differ" }, key, "bold radius: the runs differ");
    }
  }

  headlines();
  radiusAnswer();
  sweepCharts();
  details();
})();
