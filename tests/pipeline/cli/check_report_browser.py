#!/usr/bin/python3
"""`medusa report` in a real browser (headless Chromium through Selenium, network off by a dead proxy):
no SEVERE console message; one panel per type and degree; in each panel as many bars as
`medusa barcode --format csv --filtration forward` has pairs of that type and degree (capped by
--max-bars), each in a row at least a pixel tall; a pointer in a bar's row names that bar (not an
overlapping neighbour) with the birth and death times and the CC3D ids of the cells that formed
and killed the class, checked against the store itself (h5py: /persistence, /cells, /input); the
CROCKER plot of a sweep next to the store is shown; a panel with more classes than --max-bars draws those
seen longest in the tissue, and a never-filled loop or cavity is solid until its ring or shell broke
open, as `medusa classes` gives it (`seen`); the page renders (a non-blank screenshot); the
classes section agrees with `medusa classes` and `medusa at` (report_classes_check.py).

The answer on top, for the sorting runs and the control at the default radius, `medusa run` +
`medusa report` as a user types them: each run's verdict and each type's clusters at the first frame
and from when it is one cluster agree with b0 of K_t at the frames from `medusa sweep` at the store's
radius; the sorting runs sort and the control does not; the radii at which the runs differ, stated per
type, and the table of clusters per radius equal those derived here from `medusa sweep` CSVs at the
documented default radii; the page says the sweep was computed at report time; "joins", never
"merges"; the H0 panels are zoomed to the joins.

Usage: check_report_browser.py <medusa> <source dir> <workdir> [screenshot.png [class.png]]"""
import csv
import io
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
from collections import Counter
from decimal import ROUND_HALF_UP, Decimal

import h5py
import numpy as np
from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.actions.action_builder import ActionBuilder

from report_classes_check import check_classes

medusa, source, work = sys.argv[1:4]
screenshot_copy = os.path.abspath(sys.argv[4]) if len(sys.argv) > 4 else None
class_screenshot = os.path.abspath(sys.argv[5]) if len(sys.argv) > 5 else None
MAX_BARS = 300
# The class of sorting_3d selected last on one.html, whose 3D view is saved as the class screenshot:
# (type, degree, class id as `medusa classes` lists it).
CLASS_SHOWN = ("1", 1, 884)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.chdir(work)


def call(*args):
    result = subprocess.run([medusa, *args], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"medusa {' '.join(args)}: exit {result.returncode}\n{result.stderr}")
    return result.stdout


runs = {"sorting_3d": f"{source}/examples/sorting_3d", "nosorting_3d": f"{source}/tests/data/cc3d/nosorting_3d",
        "sorting_3d_seed2": f"{source}/tests/data/cc3d/sorting_3d_seed2"}
SORTING = {"sorting_3d": True, "nosorting_3d": False, "sorting_3d_seed2": True}
for name, folder in runs.items():
    call("run", folder, "-o", f"{name}.h5", "--quiet")
# A store with a sweep named like it beside it: the report shows that sweep's CROCKER plot.
os.makedirs("filed")
call("run", runs["sorting_3d"], "--radius", "3", "-o", "filed/sorting_3d.h5", "--quiet")
call("sweep", runs["sorting_3d"], "--radii", "2:4:0.5", "-o", "filed/sorting_3d", "--quiet")
call("report", "filed/sorting_3d.h5", "-o", "one.html", "--max-bars", str(MAX_BARS), "-q")
# The stores of `medusa run` alone: the report computes its radius sweep itself.
call("report", *[f"{n}.h5" for n in runs], "-o", "three.html", "--max-bars", str(MAX_BARS), "-q")


def store_radius(store):
    return re.search(r"^radius: (\S+)$", call("info", store), re.M).group(1)


def b0_table(crocker_csv):
    """(run-independent) radius -> type -> [b0 at each frame], frame times."""
    table, times = {}, set()
    with open(crocker_csv) as f:
        for r in csv.DictReader(f):
            table.setdefault(Decimal(r["radius"]), {}).setdefault(r["type"], []).append((float(r["time"]), int(r["b0"])))
            times.add(float(r["time"]))
    return {radius: {t: [b for _, b in sorted(v)] for t, v in types.items()} for radius, types in table.items()}, sorted(times)


# Oracles from `medusa sweep`: b0 at the frames at each store's own radius, and at the default radii of
# the report (r/2 to 3r/2 in steps of r/8, rounded half up to 0.01, r the first store's radius).
own = {}
for name, folder in runs.items():
    radius = store_radius(f"{name}.h5")
    call("sweep", folder, "--radius", radius, "-o", f"oracle_own_{name}", "--quiet")
    own[name] = b0_table(f"oracle_own_{name}.crocker.csv")
first_radius = Decimal(store_radius("sorting_3d.h5"))
default_radii = [(first_radius * k / 8).quantize(Decimal("0.01"), rounding=ROUND_HALF_UP) for k in range(4, 13)]
swept = {}
for name, folder in runs.items():
    call("sweep", folder, *sum((["--radius", str(r)] for r in default_radii), []), "-o", f"oracle_{name}", "--quiet")
    swept[name] = b0_table(f"oracle_{name}.crocker.csv")[0]


def expected_counts(store):
    """(type, dimension) -> number of forward pairs of positive length, from the CSV export."""
    text = call("barcode", store, "--format", "csv", "--filtration", "forward")
    return Counter((r["type"], int(r["dimension"])) for r in csv.DictReader(io.StringIO(text)))


class Store:
    """The store read directly: pairs by birth cell, cells' vertices, vertices' CC3D ids."""

    def __init__(self, path):
        with h5py.File(path, "r") as f:
            self.cc3d = f["input/cell_id"][:]
            c = f["cells"]
            ids, off, verts = c["id"][:], c["vertex_offset"][:], c["vertices"][:]
            self.vertices = {int(ids[i]): verts[off[i]:off[i + 1]] for i in range(len(ids))}
            self.pairs = {}
            for name in f["persistence"].attrs["diagram_order"].decode().split(","):
                g = f["persistence"][name]
                if g.attrs["direction"].decode() != "forward":
                    continue
                label = "all" if int(g.attrs["type"]) == -1 else str(int(g.attrs["type"]))
                for b, d, k, bc, dc, e in zip(g["birth"][:], g["death"][:], g["dimension"][:], g["birth_cell"][:],
                                              g["death_cell"][:], g["essential"][:]):
                    self.pairs.setdefault((label, int(k), int(bc)), []).append((b, d, int(dc), bool(e)))

    def cc3d_ids(self, cell):
        return sorted(int(self.cc3d[v]) for v in self.vertices[cell])


def close(a, b):
    return abs(a - b) <= 1e-5 * max(1.0, abs(b))


_classes = {}


def seen_key(c):
    """The order of `medusa classes --sort seen`: time seen in the tissue, then lifetime."""
    return (-math.inf if c["seen"] is None else c["seen"], math.inf if c["essential"] else c["lifetime"])


def classes_of(store, key):
    """{medusa birth cell: class} of `medusa classes --format json` for (type, degree)."""
    if (store, key) not in _classes:
        text = call("classes", store, "--type", key[0], "--dim", str(key[1]), "--format", "json")
        _classes[(store, key)] = {c["medusa_birth_cell"]: c for c in json.loads(text)["classes"]}
    return _classes[(store, key)]


def bars_wanted(store, key, total):
    """Bars a panel draws: all, or the MAX_BARS seen longest; in a 3D run's loop or cavity panel the
    classes never whole at one time all or none, so fewer when they do not all fit."""
    if total <= MAX_BARS or key[1] == 0:
        return min(total, MAX_BARS)
    whole = sum(1 for c in classes_of(store, key).values() if c["seen"] is not None)
    return min(whole, MAX_BARS)


def check_seen_bars(driver, panel, ri, store, key, failures, where):
    """A panel cut to --max-bars draws the classes seen longest (the `seen` of `medusa classes`, ties
    either way); each essential loop's or cavity's row carries birth + seen (null: never whole), and
    one solid overlay is drawn on each such bar whole for a positive time. Returns (overlays, cut)."""
    by_cell = classes_of(store, key)
    pi = int(panel.find_element("css selector", ".bar").get_attribute("data-panel"))
    run = driver.execute_script(
        "const r = JSON.parse(document.getElementById('report-data').textContent).runs[arguments[0]];"
        "return {pairs: r.panels[arguments[1]].pairs, dimension: r.facts.dimension};", ri, pi)
    pairs, bubbles = run["pairs"], key[1] >= run["dimension"]
    drawn = {p[2] for p in pairs}
    if not drawn <= set(by_cell):
        failures.append(f"{where}: bars of classes `medusa classes` does not list: {sorted(drawn - set(by_cell))[:5]}")
        return 0, False
    left = [seen_key(c) for cell, c in by_cell.items() if cell not in drawn]
    if left and max(left) > min(seen_key(by_cell[cell]) for cell in drawn):
        failures.append(f"{where}: a class seen {max(left)} is left out while one seen "
                        f"{min(seen_key(by_cell[cell]) for cell in drawn)} is drawn")
    overlays = 0
    for p in pairs:
        c = by_cell[p[2]]
        if not c["essential"] or bubbles:
            if len(p) > 6:
                failures.append(f"{where}: class {c['id']} (filled, or a planar run's bubble) has a time whole {p[6]}")
            continue
        expected = None if c["seen"] is None else c["birth"] + c["seen"]
        got = p[6] if len(p) > 6 else "absent"
        if got == "absent" or (expected is None) != (got is None) or (expected is not None and not close(got, expected)):
            failures.append(f"{where}: class {c['id']} whole until {got}, `medusa classes` gives {expected}")
        if expected is not None and expected > c["birth"]:
            overlays += 1
    shown = len(panel.find_elements("css selector", ".bar-whole"))
    if shown != overlays:
        failures.append(f"{where}: {shown} solid overlays on never-filled classes, expected {overlays}")
    return overlays, bool(left)


def check_answer(driver, failures):
    """The answer on top of three.html against the oracles from `medusa sweep`."""
    text = driver.execute_script("return document.body.innerText")
    if re.search(r"merg", text, re.I):
        failures.append("three.html: says 'merge' (the word is 'join')")
    if "computed at report time" not in text or ", ".join(str(r).rstrip("0").rstrip(".") for r in default_radii) not in text:
        failures.append("three.html: does not say that the radius sweep was computed at report time, at which radii")
    for ri, name in enumerate(runs):
        table, times = own[name]
        b0 = next(iter(table.values()))
        gathered = {}
        for label in ("1", "2"):
            series = b0[label]
            start = len(series)
            while start > 0 and series[start - 1] == 1:
                start -= 1
            line = driver.find_element("css selector", f".run-card[data-run='{ri}'] .headline[data-type='{label}']").text
            if not line.startswith(f"type {label}") or f"{series[0]} clusters at MCS {times[0]:.0f}" not in line:
                failures.append(f"three.html {name} type {label}: {line!r} does not start with {series[0]} clusters")
            if series[0] > 1 and start < len(series):
                gathered[label] = times[start]
                if f"one cluster from MCS {times[start]:.0f} to the end" not in line:
                    failures.append(f"three.html {name} type {label}: {line!r}, expected one cluster from MCS {times[start]:.0f}")
            elif "never one cluster" not in line and "split again" not in line and series[0] > 1:
                failures.append(f"three.html {name} type {label}: {line!r} does not say it never stays one cluster")
        # The contact fractions under each type are those `medusa curves` prints for the same store (their
        # values checked against counts on `medusa at` exports by check_sorting_measures.py); in a sorting
        # run the condensing type's heterotypic contacts fall.
        curves_text = call("curves", f"{name}.h5", "-o", f"curves_{name}")
        printed = {m.group(1): m.group(2) for m in re.finditer(
            r"^  (?:type (\d+)(?: \([^)]*\))?|all cells): (heterotypic contacts \S+ -> \S+, same-type neighbours \S+ -> \S+),",
            curves_text, re.M) if m.group(1)}
        largest = {m.group(1): m.groups()[1:] for m in re.finditer(
            r"^  type (\d+)(?: \([^)]*\))?: .*, largest cluster (\d+) -> (\d+) cells$", curves_text, re.M)}
        for label in ("1", "2"):
            shown = driver.find_element(
                "css selector", f".run-card[data-run='{ri}'] .headline[data-type='{label}'] .contacts").text
            a, b = largest.get(label, ("?", "?"))
            expected = printed.get(label, "?").replace(" -> ", " \u2192 ")
            if not re.fullmatch(re.escape(f"{expected}, largest cluster {a} of ") + r"\d+" +
                                re.escape(f" \u2192 {b} of ") + r"\d+ cells \(MCS .*\)", shown):
                failures.append(f"three.html {name} type {label}: contacts {shown!r}, `medusa curves` says {expected!r}")
        if SORTING[name]:
            first, last = (float(x) for x in re.search(r"heterotypic contacts (\S+) -> (\S+),", printed["1"]).groups())
            if not last < first:
                failures.append(f"{name}: type 1's heterotypic contacts do not fall ({first} -> {last})")
        verdict = driver.find_element("css selector", f".verdict[data-run='{ri}']").text
        if verdict.startswith(f"{name} sorts") != bool(gathered) or bool(gathered) != SORTING[name]:
            failures.append(f"three.html {name}: verdict {verdict!r}; types one cluster to the end: {gathered}, "
                            f"expected {'a sorting run' if SORTING[name] else 'the control'}")
        for label, t in gathered.items():
            if f"type {label}" not in verdict or f"by MCS {t:.0f}" not in verdict:
                failures.append(f"three.html {name}: verdict {verdict!r} does not name type {label} by MCS {t:.0f}")
        # Without a gathering type the verdict says how far each type got: its clusters at the first and
        # last frame (from `medusa sweep`) and its heterotypic contacts (from `medusa curves`).
        if not gathered:
            for label in ("1", "2"):
                first, last = b0[label][0], b0[label][-1]
                if first == 1 and all(c == 1 for c in b0[label]):
                    how = "is one cluster throughout"
                elif first == last:
                    how = f"has {first if first > 1 else 'one'} cluster{'s' if first > 1 else ''} at the first and at the last frame"
                else:
                    how = f"goes from {first if first > 1 else 'one'} cluster{'s' if first > 1 else ''} to {last if last > 1 else 'one'}"
                contacts = printed.get(label, "?").split(",")[0].replace(" -> ", " \u2192 ")
                # Between the two, the cells outside the largest cluster (checked against GUDHI by
                # check_sorting_measures.py).
                said = re.search(re.escape(how) + r"(?: \(the largest holds \d+ of its \d+ cells[^)]*\))?, " +
                                 re.escape(contacts), verdict)
                if f"type {label}" not in verdict or not said:
                    failures.append(f"three.html {name}: verdict {verdict!r} does not say type {label} {how}, {contacts}")
    # At which radii the runs differ: one cluster at the last frame in some runs but not in all.
    for label in ("1", "2"):
        differ = [r for r in default_radii
                  if len({swept[n][r][label][-1] == 1 for n in runs}) > 1]
        items = driver.find_elements("css selector", f".radius-statement[data-type='{label}']")
        if len(items) != 1:
            failures.append(f"three.html: {len(items)} radius statements for type {label}")
            continue
        shown = [Decimal(x) for x in items[0].get_attribute("data-radii").split(",") if x]
        if shown != differ:
            failures.append(f"three.html type {label}: the runs differ at radii {shown} on the page, {differ} from medusa sweep")
        wording = (f"differ at radi{'us' if len(differ) == 1 else 'i'} {differ[0].normalize()}" if differ
                   else "do not differ")
        if wording not in items[0].text.replace("E+0", ""):
            failures.append(f"three.html type {label}: statement {items[0].text!r} lacks {wording!r}")
        print(f"type {label}: the runs differ at radii {[str(r) for r in differ]}")
        for ri, name in enumerate(runs):
            for r in default_radii:
                cells = driver.find_elements(
                    "css selector", f".radius-table[data-type='{label}'] tr:nth-child({ri + 2}) td[data-radius='{r.normalize()}']")
                want = f"{swept[name][r][label][0]} → {swept[name][r][label][-1]}"
                if len(cells) != 1 or cells[0].text != want:
                    failures.append(f"three.html type {label} {name} radius {r}: table shows "
                                    f"{[c.text for c in cells]}, medusa sweep {want}")
    # The sorting runs' type 1 joins end early: its H0 panel is zoomed.
    axis = driver.execute_script("""return [...document.querySelectorAll(".panel[data-run='0'][data-type='1'][data-dim='0'] text")]
        .map((t) => t.textContent).join(" | ");""")
    if "zoomed to the joins" not in axis:
        failures.append(f"three.html: the type 1 H0 panel of sorting_3d is not zoomed: {axis!r}")
    # An H0 panel without a join (one cluster from the first frame on) is not zoomed: nothing to zoom to.
    unjoined = driver.execute_script("""const data = JSON.parse(document.getElementById("report-data").textContent);
        const out = [];
        data.runs.forEach((run, ri) => run.panels.forEach((p) => {
          if (p.dim !== 0 || p.pairs.some((x) => x[1] !== null)) return;
          const texts = [...document.querySelectorAll(`.panel[data-run='${ri}'][data-type='${p.label}'][data-dim='0'] text`)];
          out.push([run.name, p.label, texts.map((t) => t.textContent).join(" | ")]);
        }));
        return out;""")
    if not unjoined:
        failures.append("three.html: no H0 panel without a join (the check of the unzoomed panel ran on none)")
    for name, label, axis in unjoined:
        if "zoomed" in axis:
            failures.append(f"three.html: {name} {label} H0 has no join but its panel is zoomed: {axis!r}")


options = Options()
for argument in ["--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1400,1000",
                 "--proxy-server=127.0.0.1:9"]:
    options.add_argument(argument)
options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
failures = []
hovered = 0
class_clicks = 0
seen_overlays, seen_cuts = 0, 0
try:
    for page, stores in [("one.html", ["filed/sorting_3d"]), ("three.html", list(runs))]:
        driver.get("file://" + os.path.abspath(page))
        time.sleep(0.3)
        severe = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
        if severe:
            failures.append(f"{page}: console errors {severe}")
        panels = driver.find_elements("css selector", ".panel")
        if len(panels) != 9 * len(stores):  # types all, 1, 2 x degrees 0, 1, 2
            failures.append(f"{page}: {len(panels)} panels, expected {9 * len(stores)}")
        if not driver.find_elements("css selector", "svg.crocker .crocker-panel"):
            failures.append(f"{page}: no CROCKER plot")
        if len(stores) > 1 and not driver.find_elements("css selector", ".comparison-figure svg"):
            failures.append(f"{page}: no distance heat map for two stores")
        # Every label of a drawing (tick labels at the ends of the axes, run names under the
        # dendrogram, which the page scales down) must stay inside it, not be cut off at its edge.
        clipped = driver.execute_script("""
            const out = [];
            for (const svg of document.querySelectorAll('.comparison-figure svg, .panel svg, svg.chart')) {
              const box = svg.getBoundingClientRect();
              for (const t of svg.querySelectorAll('text')) {
                const r = t.getBoundingClientRect();
                if (r.left < box.left - 1 || r.right > box.right + 1 || r.top < box.top - 1 || r.bottom > box.bottom + 1)
                  out.push(t.textContent);
              }
            }
            return out;""")
        if clipped:
            failures.append(f"{page}: labels cut off at the edge of their drawing: {sorted(set(clipped))}")
        for ri, name in enumerate(stores):
            expected = expected_counts(f"{name}.h5")
            store = Store(f"{name}.h5")
            drawn_total = 0
            for panel in driver.find_elements("css selector", f".panel[data-run='{ri}']"):
                key = (panel.get_attribute("data-type"), int(panel.get_attribute("data-dim")))
                bars = panel.find_elements("css selector", ".bar")
                want = bars_wanted(f"{name}.h5", key, expected[key])
                caption = panel.find_element("css selector", ".count").text
                if want < min(expected[key], MAX_BARS) and f"the other {expected[key] - want}, never whole" not in caption:
                    failures.append(f"{page} {name} {key}: {want} bars drawn but the caption does not say why: {caption!r}")
                drawn_total += len(bars)
                if len(bars) != want or int(panel.get_attribute("data-total")) != expected[key]:
                    failures.append(f"{page} {name} {key}: {len(bars)} bars of {panel.get_attribute('data-total')}, "
                                    f"expected {want} of {expected[key]}")
                if key[1] >= 1 and bars:
                    overlays, cut = check_seen_bars(driver, panel, ri, f"{name}.h5", key, failures, f"{page} {name} {key}")
                    seen_overlays += overlays
                    seen_cuts += cut
                # Every bar has a row of at least a pixel, so the pointer can reach each one.
                if bars and float(panel.find_element("css selector", "svg.barcode").get_attribute("data-row-height")) < 1:
                    failures.append(f"{page} {name} {key}: {len(bars)} bars in rows less than a pixel apart")
                # Hover the first, middle and last bar of each panel, and the middle one's neighbours, each
                # at a pixel of its own row (rows are at least a pixel tall, so one pixel's centre lies in
                # each): the tooltip must name that bar, marked as pointed at, and agree with the store.
                middle = len(bars) // 2
                chosen = sorted({0, max(0, middle - 1), middle, min(len(bars) - 1, middle + 1), len(bars) - 1}) if bars else []
                row = float(panel.find_element("css selector", "svg.barcode").get_attribute("data-row-height")) if bars else 0
                for j in chosen:
                    bar = bars[j]
                    driver.execute_script("arguments[0].scrollIntoView({block: 'center'});", bar)
                    left, top, width = driver.execute_script(
                        "const r = arguments[0].getBoundingClientRect(); return [r.left, r.top, r.width];", bar)
                    x, y = math.floor(left + width / 2), math.ceil(top - 0.5)
                    if not y + 0.5 < top + row:
                        failures.append(f"{page} {name} {key}: no pixel centre in the row of bar {j} (top {top}, rows {row} px)")
                        continue
                    actions = ActionBuilder(driver)
                    actions.pointer_action.move_to_location(x, y)
                    actions.perform()
                    tip = driver.find_element("id", "tooltip")
                    text = tip.text
                    m = re.search(r"birth: MCS (\S+) \(medusa cell (\d+), an? [\w-]+ of CC3D cells? ([\d, ]+)\)", text)
                    if not tip.is_displayed() or not m:
                        failures.append(f"{page} {name} {key}: bar {j}: tooltip not shown or unreadable: {text!r}")
                        continue
                    birth, cell = float(m.group(1)), int(m.group(2))
                    ids = sorted(int(x) for x in m.group(3).split(","))
                    pointed = [b.get_attribute("data-pair") for b in panel.find_elements("css selector", ".bar.pointed")]
                    if pointed != [str(j)] or int(bar.get_attribute("data-birth-cell")) != cell:
                        failures.append(f"{page} {name} {key}: pointer in the row of bar {j}, bars marked {pointed}, "
                                        f"tooltip for medusa cell {cell}, the bar's {bar.get_attribute('data-birth-cell')}")
                    candidates = store.pairs.get((key[0], key[1], cell), [])
                    if not candidates or not any(close(birth, b) for b, _, _, _ in candidates):
                        failures.append(f"{page} {name} {key}: no stored pair born at MCS {birth} in cell {cell}")
                        continue
                    if ids != store.cc3d_ids(cell):
                        failures.append(f"{page} {name} {key}: birth ids {ids}, store {store.cc3d_ids(cell)}")
                    b, d, dc, essential = next(p for p in candidates if close(birth, p[0]))
                    if essential:
                        if "death: never" not in text:
                            failures.append(f"{page} {name} {key}: essential class not shown as never dying: {text!r}")
                    else:
                        md = re.search(r"death: MCS (\S+) \(medusa cell (\d+), an? [\w-]+ of CC3D cells? ([\d, ]+)\)", text)
                        if not md or int(md.group(2)) != dc or not close(float(md.group(1)), d):
                            failures.append(f"{page} {name} {key}: death {md and md.groups()}, store {d} cell {dc}")
                        elif sorted(int(x) for x in md.group(3).split(",")) != store.cc3d_ids(dc):
                            failures.append(f"{page} {name} {key}: death ids {md.group(3)}, store {store.cc3d_ids(dc)}")
                        m_life = re.search(r"lifetime: (\S+) MCS", text)
                        if not m_life or not close(float(m_life.group(1)), d - b):
                            failures.append(f"{page} {name} {key}: lifetime {m_life and m_life.group(1)}, store {d - b}")
                    hovered += 1
            if drawn_total == 0:
                failures.append(f"{page} {name}: no bars drawn")
            print(f"{page} {name}: {drawn_total} bars in {len(expected)} panels with pairs")
        # The README's class is one of sorting_3d at radius 3 (one.html); at the default radius ids differ.
        class_clicks += check_classes(driver, call, page, stores, failures, class_screenshot if page == "one.html" else None,
                                      CLASS_SHOWN if page == "one.html" else None)
        severe = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
        if severe:
            failures.append(f"{page}: console errors after selecting classes {severe}")
        if page == "three.html":
            # The README's picture: tall enough for the answer and the first table of the radii.
            driver.set_window_size(1400, 1180)
        driver.execute_script("window.scrollTo(0, 0)")
        time.sleep(0.2)
        png = f"{page}.png"
        driver.save_screenshot(png)
        pixels = np.asarray(Image.open(png).convert("RGB")).reshape(-1, 3)
        colours = len(np.unique(pixels, axis=0))
        ink = np.mean(np.any(pixels < 200, axis=1))
        if colours < 20 or ink < 0.02:
            failures.append(f"{page}: screenshot looks blank ({colours} colours, {ink:.3f} of pixels drawn)")
        if page == "three.html":
            check_answer(driver, failures)
            scripted_verdicts = [v.text for v in driver.find_elements("css selector", "#headlines .verdict")]
        if screenshot_copy and page == "three.html":
            Image.open(png).convert("RGB").quantize(colors=128).save(screenshot_copy, optimize=True)
    # The drawings `medusa run` writes next to the store: no text runs past the edge of the page. At
    # the default radius sorting_3d has essential H3 classes, which the captions mention.
    call("run", runs["sorting_3d"], "-o", "default_radius.h5", "--quiet")
    for picture in ["default_radius.barcode.svg", "default_radius.diagram.svg", "filed/sorting_3d.crocker.svg"]:
        driver.get("file://" + os.path.abspath(picture))
        outside = driver.execute_script("""
            const svg = document.documentElement, w = svg.width.baseVal.value, h = svg.height.baseVal.value;
            return [...svg.querySelectorAll('text')].filter((t) => {
              const b = t.getBBox();
              const m = t.getCTM();
              const x0 = m.a * b.x + m.c * b.y + m.e, y0 = m.b * b.x + m.d * b.y + m.f;
              const x1 = m.a * (b.x + b.width) + m.c * (b.y + b.height) + m.e;
              const y1 = m.b * (b.x + b.width) + m.d * (b.y + b.height) + m.f;
              return Math.min(x0, x1) < -1 || Math.max(x0, x1) > w + 1 || Math.min(y0, y1) < -1 || Math.max(y0, y1) > h + 1;
            }).map((t) => t.textContent);""")
        if outside:
            failures.append(f"{picture}: text past the edge of the page: {outside}")
finally:
    driver.quit()

# With JavaScript off (a mail client, a file preview) the page still gives each run's verdict, the
# same words report.js writes.
options.add_experimental_option("prefs", {"profile.managed_default_content_settings.javascript": 2})
driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
try:
    driver.get("file://" + os.path.abspath("three.html"))
    time.sleep(0.3)
    if driver.find_elements("css selector", ".panel"):
        failures.append("three.html without JavaScript: panels were drawn, so JavaScript ran")
    plain = [v.text for v in driver.find_elements("css selector", "noscript .verdict")]
    if len(scripted_verdicts) != len(runs) or plain != scripted_verdicts:
        failures.append(f"three.html without JavaScript: verdicts {plain}, with it {scripted_verdicts}")
    print(f"without JavaScript: {len(plain)} verdicts shown, as with it")
finally:
    driver.quit()

print(f"{hovered} hovers checked against the store, {class_clicks} classes selected; {seen_overlays} never-filled "
      f"classes drawn solid while whole, {seen_cuts} panels cut to those seen longest")
if seen_overlays == 0 or seen_cuts == 0:
    failures.append("no never-filled class drawn solid, or no panel cut to the classes seen longest: nothing checked")
if hovered == 0:
    failures.append("no bar hovered")
if class_clicks == 0:
    failures.append("no class selected")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
