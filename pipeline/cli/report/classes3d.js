// The classes section of the report: per run, the classes of each cell type and degree seen longest in the tissue
// with the CC3D cells of their representatives (docs/MATH.md §7.11), and a 3D view (three.js) of the
// cells at a chosen time with the selected class's cells, edges and triangles highlighted. Positions
// between the embedded frames are interpolated as `medusa at` does (linear between the frames around
// the time; a cell present on one of the two frames only stays where it is there). Clicking a row
// selects its class; window.medusaReport exposes the selection and the positions to scripts.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("report-data").textContent);
  const typeColours = ["#7f7f7f", "#e6550d", "#3182bd", "#31a354", "#756bb1", "#8c564b", "#e377c2", "#17becf"];
  const views = [];

  const { html, fmt, typeTitle, degreeName: names } = window.medusaReportText;
  function typeColour(type) { return typeColours[((type % typeColours.length) + typeColours.length) % typeColours.length]; }
  function list(ids, limit) {
    if (ids.length <= limit) return ids.join(" ");
    return ids.slice(0, limit).join(" ") + " … (+" + (ids.length - limit) + ")";
  }
  function deathWord(k) { return k === 0 ? "joined" : "filled"; }

  // Positions of every trajectory at time t: [x, y, z] or null, interpolated between the embedded frames.
  function positionsAt(classes, t) {
    const F = classes.frames.times, P = classes.frames.positions, n = classes.cells.cc3d.length;
    let k = 0;
    while (k + 2 < F.length && F[k + 1] <= t) ++k;
    const next = Math.min(k + 1, F.length - 1), span = F[next] - F[k];
    const u = span > 0 ? Math.min(1, Math.max(0, (t - F[k]) / span)) : 0;
    const out = new Array(n);
    for (let v = 0; v < n; ++v) {
      const here = P[k][3 * v] !== null, there = P[next][3 * v] !== null;
      if (!here && !there) { out[v] = null; continue; }
      const a = here ? P[k] : P[next], b = there ? P[next] : P[k], x = [0, 0, 0];
      for (let i = 0; i < 3; ++i) x[i] = a[3 * v + i] + u * (b[3 * v + i] - a[3 * v + i]);
      out[v] = x;
    }
    return out;
  }

  // On a periodic run, the positions to draw: the class's cells placed along its edges, each at the
  // periodic image nearest to its neighbour (an edge is shorter than half a period, docs/MATH.md §8.3),
  // and every other cell at its image nearest to the class's centre.
  function periodicImages(classes, cls, pos) {
    const L = classes.periodic_lengths;
    if (!L.some((l) => l > 0)) return pos;
    const near = (x, ref) => x.map((xi, a) => (L[a] > 0 ? xi + L[a] * Math.round((ref[a] - xi) / L[a]) : xi));
    const out = pos.slice(), placed = new Set();
    if (cls) {
      const adjacent = new Map();
      const link = (a, b) => { if (!adjacent.has(a)) adjacent.set(a, []); adjacent.get(a).push(b); };
      const pairs = [...cls.edges];
      for (const s of [cls.birth_simplex, cls.death_simplex])
        for (let i = 0; i < s.length; ++i) for (let j = i + 1; j < s.length; ++j) pairs.push([s[i], s[j]]);
      for (const [a, b] of pairs) { link(a, b); link(b, a); }
      const roots = cls.vertices.concat(cls.birth_simplex, cls.death_simplex);
      for (const root of roots) {
        if (placed.has(root) || !pos[root]) continue;
        if (placed.size) out[root] = near(pos[root], out[[...placed][0]]);
        placed.add(root);
        const queue = [root];
        while (queue.length) {
          const a = queue.shift();
          for (const b of adjacent.get(a) || []) {
            if (placed.has(b) || !pos[b]) continue;
            out[b] = near(pos[b], out[a]);
            placed.add(b);
            queue.push(b);
          }
        }
      }
    }
    const mine = [...placed];
    const all = mine.length ? mine.map((v) => out[v]) : pos.filter((x) => x);
    const c = [0, 1, 2].map((i) => all.reduce((sum, x) => sum + x[i], 0) / Math.max(1, all.length));
    pos.forEach((x, v) => { if (x && !placed.has(v)) out[v] = near(x, c); });
    return out;
  }

  // Typical distance between neighbouring cells (median nearest-neighbour distance of a sample), for the
  // size of the spheres.
  function cellSpacing(pos) {
    const present = pos.filter((x) => x !== null);
    if (present.length < 2) return 1;
    const step = Math.max(1, Math.floor(present.length / 300)), d = [];
    for (let i = 0; i < present.length; i += step) {
      let best = Infinity;
      for (let j = 0; j < present.length; ++j) {
        if (j === i) continue;
        const dx = present[i][0] - present[j][0], dy = present[i][1] - present[j][1], dz = present[i][2] - present[j][2];
        best = Math.min(best, dx * dx + dy * dy + dz * dz);
      }
      d.push(Math.sqrt(best));
    }
    d.sort((a, b) => a - b);
    return d[Math.floor(d.length / 2)] || 1;
  }

  // The unit direction along which the points spread least (the smallest eigenvector of their
  // covariance, by power iteration on trace - covariance); z when there are too few points.
  function leastSpreadDirection(pts, c) {
    if (pts.length < 3) return [0.3, -0.5, 0.8];
    const C = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
    for (const x of pts) for (let i = 0; i < 3; ++i) for (let j = 0; j < 3; ++j) C[i][j] += (x[i] - c[i]) * (x[j] - c[j]);
    const tr = C[0][0] + C[1][1] + C[2][2] || 1;
    let v = [0.3, -0.5, 0.8];
    for (let it = 0; it < 100; ++it) {
      const w = [0, 1, 2].map((i) => tr * v[i] - (C[i][0] * v[0] + C[i][1] * v[1] + C[i][2] * v[2]));
      const n = Math.hypot(...w) || 1;
      v = w.map((x) => x / n);
    }
    return v;
  }

  function labelSprite(text, size) {
    const canvas = document.createElement("canvas"), ctx = canvas.getContext("2d");
    canvas.width = 128; canvas.height = 64;
    ctx.font = "bold 40px sans-serif";
    ctx.textAlign = "center"; ctx.textBaseline = "middle";
    ctx.lineWidth = 8; ctx.strokeStyle = "white"; ctx.strokeText(text, 64, 32);
    ctx.fillStyle = "#111"; ctx.fillText(text, 64, 32);
    const texture = new THREE.CanvasTexture(canvas);
    const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: texture, depthTest: false, transparent: true }));
    sprite.scale.set(size * 2, size, 1);
    sprite.renderOrder = 10;
    return sprite;
  }

  function makeView(ri, run, parent) {
    const classes = run.classes;
    const view = { ri: ri, run: run, classes: classes, section: null, cls: null, time: run.facts.t0, three: null,
      drawn: [], absent: [], context: "all" };
    const box = html("div", { class: "view3d", "data-run": ri }, parent);
    const canvasBox = html("div", { class: "view3d-canvas" }, box);
    const controls = html("div", { class: "view3d-controls" }, box);
    html("label", { for: "class-time-" + ri }, controls, "MCS ");
    const slider = html("input", { type: "range", id: "class-time-" + ri, class: "class-time",
      min: run.facts.t0, max: run.facts.t_end, step: "any", value: run.facts.t0 }, controls);
    const number = html("input", { type: "number", class: "class-time-number", min: run.facts.t0, max: run.facts.t_end,
      step: "any", value: run.facts.t0 }, controls);
    const toBirth = html("button", { type: "button", class: "to-birth" }, controls, "birth");
    const toDeath = html("button", { type: "button", class: "to-death" }, controls, "death");
    const context = html("select", { class: "class-context" }, controls);
    for (const [value, text] of [["all", "other cells: all"], ["type", "other cells: this type"], ["none", "other cells: none"]])
      html("option", { value: value }, context, text);
    view.caption = html("div", { class: "view3d-caption" }, box);
    const legend = html("div", { class: "view3d-legend" }, box);
    const typeIds = [...new Set(classes.cells.type)].sort((a, b) => a - b);
    for (const t of typeIds) {
      const f = run.facts.types.find((x) => x.id === t);
      const s = html("span", {}, legend);
      html("i", { style: "background:" + typeColour(t) }, s);
      s.appendChild(document.createTextNode("type " + t + (f && f.name ? " " + f.name : "")));
    }
    for (const [colour, text] of [["#222", "the class's edges (contacts between its cells by the time it formed)"], ["#f2b701", "its triangles"], ["#00a651", "the contact that formed it"],
      ["#c51b8a", "the contact that filled it or joined it to an older cluster"]]) {
      const s = html("span", {}, legend);
      html("i", { style: "background:" + colour }, s);
      s.appendChild(document.createTextNode(text));
    }
    legend.appendChild(document.createTextNode(" · pale: cells not in the class · drag to turn, wheel to zoom"));
    const note = classes.frames.times.length < classes.frames.frame_count
      ? "Positions embedded at " + classes.frames.times.length + " of the run's " + classes.frames.frame_count +
        " frames and interpolated between them. " : "";
    const periodic = classes.periodic_lengths.some((l) => l > 0);
    if (note || periodic)
      html("div", { class: "note" }, box, note + (periodic ? "Periodic run: the cells are shown around the selected " +
        "class, each at its periodic image nearest to it, so a class across the boundary stays in one piece." : ""));

    const setTime = (t, refit) => {
      view.time = Math.min(run.facts.t_end, Math.max(run.facts.t0, Number(t)));
      slider.value = view.time;
      number.value = fmt(view.time);
      draw(view, refit === true);
    };
    view.setTime = setTime;
    view.toDeath = toDeath;
    slider.addEventListener("input", () => setTime(slider.value));
    number.addEventListener("change", () => setTime(number.value));
    toBirth.addEventListener("click", () => view.cls && setTime(view.cls.birth));
    toDeath.addEventListener("click", () => view.cls && view.cls.death !== null && setTime(view.cls.death));
    context.addEventListener("change", () => { view.context = context.value; draw(view, false); });

    // Asked first: three.js reports a missing WebGL as a console error.
    const probe = document.createElement("canvas");
    const webgl = typeof THREE !== "undefined" && (probe.getContext("webgl") || probe.getContext("experimental-webgl"));
    try {
      if (!webgl) throw new Error("no WebGL");
      const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
      renderer.setPixelRatio(window.devicePixelRatio || 1);
      renderer.setClearColor(0xffffff);
      canvasBox.appendChild(renderer.domElement);
      const scene = new THREE.Scene();
      const camera = new THREE.PerspectiveCamera(40, 1, 0.1, 10000);
      const light = new THREE.DirectionalLight(0xffffff, 0.75);
      light.position.set(1, 2, 3);
      camera.add(light);
      scene.add(camera);
      scene.add(new THREE.AmbientLight(0xffffff, 0.5));
      const orbit = new THREE.OrbitControls(camera, renderer.domElement);
      const group = new THREE.Group();
      scene.add(group);
      view.three = { renderer: renderer, scene: scene, camera: camera, orbit: orbit, group: group };
      orbit.addEventListener("change", () => renderer.render(scene, camera));
      const resize = () => {
        const w = canvasBox.clientWidth || 600, h = Math.round(Math.min(560, Math.max(320, w * 0.8)));
        renderer.setSize(w, h);
        camera.aspect = w / h;
        camera.updateProjectionMatrix();
        renderer.render(scene, camera);
      };
      view.resize = resize;
      window.addEventListener("resize", resize);
    } catch (e) {
      html("p", { class: "note no-webgl" }, canvasBox, "The 3D view needs WebGL, which this browser does not offer " +
        "here; the tables list the cells of each class.");
    }
    return view;
  }

  // The cells of the selected class present at the view's time are drawn opaque in their type's colour,
  // the others pale; the class's edges, triangles and its birth and death cells between them.
  function draw(view, refit) {
    const classes = view.classes, cls = view.cls;
    let pos = positionsAt(classes, view.time);
    const inClass = new Set(cls ? cls.vertices : []);
    const sectionType = view.section && view.section.label !== "all" ? Number(view.section.label) : null;
    view.drawn = [];
    view.absent = [];
    for (const v of inClass) (pos[v] ? view.drawn : view.absent).push(classes.cells.cc3d[v]);
    const unique = (a) => [...new Set(a)].sort((x, y) => x - y);
    view.drawn = unique(view.drawn);
    view.absent = unique(view.absent).filter((id) => !view.drawn.includes(id));
    if (cls) {
      const sec = view.section, nm = names(view.run, sec.dim);
      view.caption.textContent = typeTitle(sec.label, sec.name) + " · H" + sec.dim + " " + nm[0] + " " + cls.id +
        " at MCS " + fmt(view.time) + ": born at MCS " + fmt(cls.birth) + ", " +
        (cls.death === null ? "never " + deathWord(sec.dim) + ringWords(cls.ring, sec.dim, view.run) : deathWord(sec.dim) + " at MCS " + fmt(cls.death)) +
        "; " + view.drawn.length + " cells: " + list(view.drawn, 40) +
        (view.absent.length ? " (not present at this time: " + view.absent.join(" ") + ")" : "");
    }
    if (!view.three) return;
    const { group, camera, orbit, renderer, scene } = view.three;
    pos = periodicImages(classes, cls, pos);
    while (group.children.length) {
      const c = group.children.pop();
      if (c.geometry) c.geometry.dispose();
      if (c.material) { if (c.material.map) c.material.map.dispose(); c.material.dispose(); }
    }
    if (view.spacing === undefined) view.spacing = cellSpacing(pos);
    const s = view.spacing;
    // Cells: one instanced mesh per type, for the class and for the others.
    const buckets = new Map();
    pos.forEach((x, v) => {
      if (!x) return;
      const type = classes.cells.type[v], mine = inClass.has(v);
      if (!mine && (view.context === "none" || (view.context === "type" && sectionType !== null && type !== sectionType))) return;
      const key = type + (mine ? ":class" : ":other");
      if (!buckets.has(key)) buckets.set(key, { type: type, mine: mine, xs: [] });
      buckets.get(key).xs.push(x);
    });
    const sphere = new THREE.SphereBufferGeometry(1, 20, 14);
    const m = new THREE.Matrix4();
    for (const b of buckets.values()) {
      const colour = new THREE.Color(typeColour(b.type));
      if (!b.mine) colour.lerp(new THREE.Color(0xdddddd), 0.6);
      const material = new THREE.MeshLambertMaterial({ color: colour, transparent: !b.mine, opacity: b.mine ? 1 : (cls ? 0.2 : 0.8),
        depthWrite: b.mine || !cls });
      // One geometry per instanced mesh: three.js r111 keeps the instance buffer bound while the geometry
      // and program stay the same, so meshes sharing a geometry would draw each other's instances.
      const mesh = new THREE.InstancedMesh(sphere.clone(), material, b.xs.length);
      const r = s * (b.mine ? 0.24 : 0.16);
      b.xs.forEach((x, i) => { m.makeScale(r, r, r).setPosition(x[0], x[1], x[2]); mesh.setMatrixAt(i, m); });
      mesh.instanceMatrix.needsUpdate = true;
      // The instances are far from the geometry's own bounding sphere at the origin.
      mesh.frustumCulled = false;
      if (!b.mine) mesh.renderOrder = 5;
      group.add(mesh);
    }
    if (cls) {
      const here = (vs) => vs.every((v) => pos[v]);
      const edge = (a, b, radius, colour, list) => list.push([pos[a], pos[b], radius, colour]);
      const cylinders = [];
      for (const [a, b] of cls.edges) if (pos[a] && pos[b]) edge(a, b, s * 0.08, "#222222", cylinders);
      const pairs = (vs) => { const out = []; for (let i = 0; i < vs.length; ++i) for (let j = i + 1; j < vs.length; ++j) out.push([vs[i], vs[j]]); return out; };
      if (here(cls.birth_simplex)) for (const [a, b] of pairs(cls.birth_simplex)) edge(a, b, s * 0.13, "#00a651", cylinders);
      if (cls.death_simplex.length && here(cls.death_simplex)) for (const [a, b] of pairs(cls.death_simplex)) edge(a, b, s * 0.12, "#c51b8a", cylinders);
      const cylinder = new THREE.CylinderBufferGeometry(1, 1, 1, 10);
      const byColour = new Map();
      for (const c of cylinders) { if (!byColour.has(c[3])) byColour.set(c[3], []); byColour.get(c[3]).push(c); }
      const up = new THREE.Vector3(0, 1, 0), q = new THREE.Quaternion();
      for (const [colour, list] of byColour) {
        const mesh = new THREE.InstancedMesh(cylinder.clone(), new THREE.MeshLambertMaterial({ color: colour }), list.length);
        list.forEach(([a, b, radius], i) => {
          const va = new THREE.Vector3(...a), vb = new THREE.Vector3(...b), d = vb.clone().sub(va), len = d.length();
          q.setFromUnitVectors(up, len > 0 ? d.clone().divideScalar(len) : up);
          m.compose(va.add(vb).multiplyScalar(0.5), q, new THREE.Vector3(radius, len, radius));
          mesh.setMatrixAt(i, m);
        });
        mesh.instanceMatrix.needsUpdate = true;
        mesh.frustumCulled = false;
        group.add(mesh);
      }
      const faces = (tris, colour, opacity) => {
        const xyz = [];
        for (const t of tris) if (here(t)) for (const v of t) xyz.push(...pos[v]);
        if (!xyz.length) return;
        const g = new THREE.BufferGeometry();
        g.setAttribute("position", new THREE.Float32BufferAttribute(xyz, 3));
        g.computeVertexNormals();
        group.add(new THREE.Mesh(g, new THREE.MeshLambertMaterial({ color: colour, side: THREE.DoubleSide, transparent: true,
          opacity: opacity, depthWrite: false })));
      };
      faces(cls.triangles, "#f2b701", 0.45);
      const d = cls.death_simplex;
      if (d.length >= 3) faces(d.length === 3 ? [d] : [[d[0], d[1], d[2]], [d[0], d[1], d[3]], [d[0], d[2], d[3]], [d[1], d[2], d[3]]], "#c51b8a", 0.35);
      // CC3D ids beside the class's cells, when they are few enough to read.
      const labelled = new Set();
      if (inClass.size <= 40)
        for (const v of inClass) {
          if (!pos[v] || labelled.has(classes.cells.cc3d[v])) continue;
          labelled.add(classes.cells.cc3d[v]);
          const sprite = labelSprite(String(classes.cells.cc3d[v]), s * 0.45);
          sprite.position.set(pos[v][0], pos[v][1], pos[v][2]);
          group.add(sprite);
        }
    }
    if (refit) {
      // Centre on the class (or the whole tissue) and back off to see it with its neighbourhood, looking
      // across the plane the class's cells spread least from (a loop is seen as a ring, not edge-on).
      const pts = (cls ? cls.vertices.map((v) => pos[v]) : pos).filter((x) => x);
      const all = pts.length ? pts : pos.filter((x) => x);
      const c = [0, 1, 2].map((i) => all.reduce((sum, x) => sum + x[i], 0) / Math.max(1, all.length));
      let radius = 0;
      for (const x of all) radius = Math.max(radius, Math.hypot(x[0] - c[0], x[1] - c[1], x[2] - c[2]));
      radius = Math.max(radius, 2.5 * s);
      const dist = (radius * 1.15) / Math.sin((camera.fov * Math.PI) / 360);
      const normal = leastSpreadDirection(all, c);
      const side = new THREE.Vector3(...normal).cross(new THREE.Vector3(0, 0, 1));
      if (side.length() < 1e-6) side.set(1, 0, 0);
      const eye = new THREE.Vector3(...normal).multiplyScalar(0.9).add(side.normalize().multiplyScalar(0.3)).normalize();
      orbit.target.set(c[0], c[1], c[2]);
      camera.position.set(c[0] + dist * eye.x, c[1] + dist * eye.y, c[2] + dist * eye.z);
      camera.up.set(0, 0, 1);
      if (Math.abs(eye.z) > 0.95) camera.up.set(0, 1, 0);
      camera.near = dist / 100;
      camera.far = dist * 20;
      camera.updateProjectionMatrix();
      orbit.update();
    }
    for (const sprite of group.children.filter((x) => x.isSprite)) {
      // Labels sit above their cell on the screen.
      const up = camera.up.clone().multiplyScalar(s * 0.42);
      sprite.position.add(up);
    }
    renderer.render(scene, camera);
  }

  function select(view, section, cls) {
    view.section = section;
    view.cls = cls;
    for (const tr of document.querySelectorAll(".class-row[data-run='" + view.ri + "']"))
      tr.classList.toggle("selected", tr.dataset.type === section.label && Number(tr.dataset.dim) === section.dim &&
        Number(tr.dataset.class) === cls.id);
    view.toDeath.disabled = cls.death === null;
    view.setTime(cls.birth, true);
  }

  function table(parent, view, section) {
    const run = view.run, nm = names(run, section.dim);
    const div = html("div", { class: "class-table", "data-run": view.ri, "data-type": section.label, "data-dim": section.dim,
      "data-total": section.total }, parent);
    const caption = typeTitle(section.label, section.name) + " · H" + section.dim + " " + nm[1];
    html("div", { class: "caption" }, div, caption);
    if (!section.classes.length) {
      html("div", { class: "count" }, div, "no " + nm[1] + " of positive lifetime");
      return;
    }
    html("div", { class: "count" }, div, section.classes.length === section.total
      ? section.total + " " + (section.total === 1 ? nm[0] : nm[1])
      : "the " + section.classes.length + " seen longest of " + section.total + " " + nm[1] + " (the other " +
        (section.total - section.classes.length) + ": medusa classes --type " + section.label + " --dim " + section.dim + " --sort seen)");
    const t = html("table", {}, div), head = html("tr", {}, html("thead", {}, t));
    for (const h of ["id", "born (MCS)", deathWord(section.dim) + " (MCS)", "lifetime (MCS)", "formed by cells", "killed by cells", "CC3D cells of the " + nm[0]])
      html("th", {}, head, h);
    const body = html("tbody", {}, t);
    for (const cls of section.classes) {
      const tr = html("tr", { class: "class-row", "data-run": view.ri, "data-type": section.label, "data-dim": section.dim,
        "data-class": cls.id, title: "show this " + nm[0] + " in the 3D view" }, body);
      html("td", {}, tr, String(cls.id));
      html("td", {}, tr, fmt(cls.birth));
      html("td", { class: "fate", "data-broke-at": cls.ring && cls.ring.broke_at !== null ? String(cls.ring.broke_at) : "" }, tr, cls.death === null ? "never " + deathWord(section.dim) + ringWords(cls.ring, section.dim, run) : fmt(cls.death));
      html("td", { class: "lifetime" }, tr, cls.death === null ? "≥ " + fmt(run.facts.t_end - cls.birth) + wholeFor(cls, section.dim, run) : fmt(cls.death - cls.birth));
      html("td", {}, tr, cls.birth_cells.join(" "));
      html("td", {}, tr, cls.death === null ? "–" : cls.death_cells.join(" "));
      html("td", { class: "cells", title: cls.cells.join(" ") }, tr, cls.cells.length + ": " + list(cls.cells, 12));
      tr.addEventListener("click", () => select(view, section, cls));
    }
  }

  // An essential loop or cavity is never filled; its cells' ring or shell can still have broken open
  // (pipeline/cli/ring_fate.h).
  // How long a ring or shell that broke open stayed whole: its class lives on in space-time, but the
  // cells were a ring only that long.
  function wholeFor(cls, dim, run) {
    if (!cls.ring) return "";
    if (bubble(dim, run)) return " in space-time";
    if (cls.ring.state === "never whole") return " in space-time; never a " + (dim === 2 ? "shell" : "ring") + " at one time";
    if (cls.ring.state !== "broke") return "";
    return " (a " + (dim === 2 ? "shell" : "ring") + " for " + fmt(cls.ring.broke_at - cls.birth) + ")";
  }

  // A planar run's H2 classes: holes inside the tissue that closed again, never a shell at one time
  // (docs/MATH.md §7.6).
  function bubble(dim, run) { return dim === 2 && run.facts.dimension === 2; }

  function ringWords(ring, dim, run) {
    if (!ring) return "";
    if (bubble(dim, run)) return "; a bubble of space-time (a hole inside the tissue that closed again, born when it closed)";
    const what = dim === 2 ? "shell" : "ring";
    if (ring.state === "broke") return "; this " + what + " broke open at MCS " + fmt(ring.broke_at);
    if (ring.state === "never whole") return "; a " + (dim === 2 ? "cavity" : "loop") + " of space-time only (its contacts never all at once)";
    return "; this " + what + " is whole at the end";
  }

  function build() {
    data.runs.forEach((run, ri) => {
      if (!run.classes) return;
      const parent = document.querySelector("section.run[data-run='" + ri + "']") || document.getElementById("details");
      const sec = html("div", { class: "classes", id: "classes-" + ri, "data-run": ri }, parent);
      html("h3", {}, sec, "Which cells? The classes seen longest in the tissue and the cells that make them (forward filtration)");
      html("p", { class: "note" }, sec, "Per cell type and degree, the " + run.classes.top + " classes seen longest in the tissue " +
        "(medusa classes --sort seen): a cluster, loop or cavity that joined another or was filled for its lifetime, one never " +
        "filled for as long as the ring or shell of cells it is listed with stayed whole, up to the end of the run. A class's cells are those of its representative: for a cluster the cells " +
        "in it just before it joined an older one (for a cluster that never joined one, every cell that was part of it " +
        "at some time up to the end: cells born later by division and cells that died are listed too), for a loop or a cavity the cells on a ring or a shell around it " +
        "when it formed (docs/MATH.md §7.11). A loop or cavity never filled is a class of the space-time medusa to the " +
        "end, so its lifetime reads '≥'; whether the cells it is listed with are still a ring or shell at the end, broke " +
        "open at some time, or never were a ring or shell at one time (their contacts never all present at once) is said beside it. 'Formed by' and 'killed by' are the cells whose contact created and " +
        "ended it: the last edge or triangle that closed it, the triangle or tetrahedron that filled it. Click a row " +
        "to see the class in 3D at the time it formed; move the time to watch it close and fill. The full lists: " +
        "medusa classes STORE --type T --dim K --sort seen (ids as in the first column).");
      const layout = html("div", { class: "classes-layout" }, sec);
      const view = makeView(ri, run, layout);
      views.push(view);
      const tables = html("div", { class: "class-tables" }, layout);
      const sections = run.classes.sections.filter((s) => s.label !== "all").concat(run.classes.sections.filter((s) => s.label === "all"));
      for (const s of sections) table(tables, view, s);
      if (view.resize) view.resize();
      // First shown: the loop of the first cell type seen longest, or else any class.
      const first = sections.find((s) => s.dim === 1 && s.classes.length) || sections.find((s) => s.classes.length);
      if (first) select(view, first, first.classes[0]);
      else draw(view, true);
    });
  }

  function viewOf(ri) {
    const view = views.find((v) => v.ri === (ri || 0));
    if (!view) throw new Error("no classes view for run " + ri);
    return view;
  }

  window.medusaReport = {
    // The selected class of run `ri` and the CC3D ids of its cells drawn highlighted at the view's time.
    highlighted: (ri) => {
      const v = viewOf(ri);
      return { run: v.ri, type: v.section && v.section.label, dim: v.section && v.section.dim, id: v.cls && v.cls.id,
        time: v.time, cells: v.drawn.slice(), absent: v.absent.slice(), webgl: v.three !== null };
    },
    select: (ri, label, dim, id) => {
      const v = viewOf(ri), s = v.classes.sections.find((x) => x.label === String(label) && x.dim === dim);
      const c = s && s.classes.find((x) => x.id === id);
      if (!c) throw new Error("no class " + id + " of type " + label + " in degree " + dim + " in the page");
      select(v, s, c);
    },
    setTime: (ri, t) => viewOf(ri).setTime(t),
    range: (ri) => [viewOf(ri).run.facts.t0, viewOf(ri).run.facts.t_end],
    // The cell types of these CC3D ids.
    types: (ri, ids) => {
      const c = viewOf(ri).classes.cells, want = new Set(ids), out = new Set();
      c.cc3d.forEach((id, v) => { if (want.has(id)) out.add(c.type[v]); });
      return [...out];
    },
    // {CC3D id: [x, y, z]} of the cells present at time t (the last trajectory of an id wins), before
    // any periodic image is taken.
    positions: (ri, t) => {
      const v = viewOf(ri), pos = positionsAt(v.classes, t), out = {};
      pos.forEach((x, i) => { if (x) out[v.classes.cells.cc3d[i]] = x; });
      return out;
    },
  };

  build();
})();
