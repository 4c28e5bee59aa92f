"""The classes section of a `medusa report` page, checked in the browser against `medusa classes` and
`medusa at`: each table lists the classes of its type and degree seen longest in the tissue, in the
order of `medusa classes --sort seen`, and says how many there are; clicking a row selects the class, and
exactly the CC3D cells `medusa classes --format json` gives for it are drawn highlighted (read back
through window.medusaReport and seen in the canvas as the type's colour); the positions the view
interpolates at a time between frames are those `medusa at --time T` writes."""
import re
import json
import os
import time

import numpy as np
from PIL import Image

TOP = 5


def orange(p):  # type 1 of the page's 3D view (classes3d.js, #e6550d), shaded; not the pale context
    r, g, b = p[:, 0], p[:, 1], p[:, 2]
    return (r > 80) & (g < 0.5 * r) & (b < 0.25 * r)


def blue(p):  # type 2 (#3182bd), shaded
    r, g, b = p[:, 0], p[:, 1], p[:, 2]
    return (b > 80) & (r < 0.4 * b) & (g < 0.8 * b)


TYPE_COLOURS = {1: orange, 2: blue}


def classes_json(call, store, label, dim):
    text = call("classes", store, "--type", label, "--dim", str(dim), "--format", "json", "--sort", "seen")
    return json.loads(text)["classes"]


def vtk_positions(path):
    """{CC3D id: (x, y, z)} of the points of a legacy ASCII VTK file written by `medusa at`."""
    tokens = open(path).read().split()
    i = tokens.index("POINTS")
    n = int(tokens[i + 1])
    xyz = np.array([float(t) for t in tokens[i + 3:i + 3 + 3 * n]]).reshape(n, 3)
    j = tokens.index("cell_id", tokens.index("POINT_DATA"))
    # SCALARS cell_id int 1 / LOOKUP_TABLE default / values
    k = tokens.index("default", j) + 1
    ids = [int(t) for t in tokens[k:k + n]]
    return dict(zip(ids, map(tuple, xyz)))


def simplices_at(call, store, label, t, path):
    """The simplices (tuples of CC3D ids) of type `label`'s K(t+) as `medusa at` writes them."""
    call("at", store, "--type", label, "--time", repr(t), "-o", path)
    with open(path) as f:
        next(f)
        return {tuple(int(v) for v in line.strip().split(",")[1:] if v) for line in f}


def check_ring_fates(driver, call, page, name, ri, expected, t_end, failures):
    """Each essential loop or cavity row says what became of the ring or shell it is listed with; checked
    on the complexes `medusa at` gives: a ring whole at the end has all its simplices in K(t_end-); one
    that broke open at MCS x has them all halfway from its birth to x and not all just after x."""
    checked = 0
    for cell in driver.find_elements("css selector", f".class-row[data-run='{ri}'] td.fate"):
        text = cell.text
        if not text.startswith("never") or "ring" not in text and "shell" not in text:
            continue
        row = cell.find_element("xpath", "..")
        label, dim, cid = row.get_attribute("data-type"), int(row.get_attribute("data-dim")), int(row.get_attribute("data-class"))
        if label == "all":
            continue  # `medusa at --type` takes a cell type
        want = expected[(label, dim)][cid]
        ring = {tuple(s) for s in want["simplices"]}
        store = f"{name}.h5"
        what = f"{page} {name} type {label} H{dim} class {cid} ({text!r})"
        listed = (want.get("ring") or {}).get("state")
        if listed != ("whole at the end" if "whole at the end" in text else "broke"):
            failures.append(f"{what}: `medusa classes --format json` says ring {want.get('ring')}")
        life = row.find_element("css selector", "td.lifetime").text
        m_whole = re.search(r"\(a (?:ring|shell) for (\S+)\)$", life)
        if "whole at the end" in text:
            if m_whole:
                failures.append(f"{what}: lifetime {life!r} gives a time whole to a ring whole at the end")
            if not ring <= simplices_at(call, store, label, t_end, f"ring_{ri}.csv"):
                failures.append(f"{what}: not every simplex of it is in K(t_end-)")
        else:
            x = float(cell.get_attribute("data-broke-at"))
            if not m_whole or abs(float(m_whole.group(1)) - (x - want["birth"])) > 1e-3 * max(1.0, x):
                failures.append(f"{what}: lifetime {life!r}, but the ring was whole for {x - want['birth']} MCS")
            if want.get("ring", {}).get("broke_at") != x:
                failures.append(f"{what}: broke open at MCS {x} on the page, {want.get('ring')} in `medusa classes`")
            after = simplices_at(call, store, label, x * (1 + 1e-9) + 1e-9, f"ring_{ri}.csv")
            if ring <= after:
                failures.append(f"{what}: every simplex of it is still in K just after MCS {x}")
            if want["birth"] < x:
                before = simplices_at(call, store, label, (want["birth"] + x) / 2, f"ring_{ri}.csv")
                if not ring <= before:
                    failures.append(f"{what}: not every simplex of it is in K halfway from its birth to MCS {x}")
        checked += 1
    return checked


def canvas_has_colour(view, colour, png):
    view.find_element("css selector", "canvas").screenshot(png)
    pixels = np.asarray(Image.open(png).convert("RGB")).reshape(-1, 3).astype(float)
    return int(np.sum(colour(pixels)))


def check_classes(driver, call, page, stores, failures, screenshot=None, shown=None):
    """Checks the classes section of each run of the loaded page; returns the number of clicks checked.
    `shown` = (type label, dim, class id) of sorting_3d is selected last and its view saved to `screenshot`."""
    clicks = 0
    for ri, name in enumerate(stores):
        store = f"{name}.h5"
        tables = driver.find_elements("css selector", f".class-table[data-run='{ri}']")
        if len(tables) != 9:
            failures.append(f"{page} {name}: {len(tables)} class tables, expected 9 (types all, 1, 2 x H0-H2)")
        expected = {}
        for table in tables:
            label, dim = table.get_attribute("data-type"), int(table.get_attribute("data-dim"))
            listed = classes_json(call, store, label, dim)
            expected[(label, dim)] = {c["id"]: c for c in listed}
            rows = table.find_elements("css selector", ".class-row")
            ids = [int(r.get_attribute("data-class")) for r in rows]
            want = [c["id"] for c in listed[:TOP]]
            if ids != want or int(table.get_attribute("data-total")) != len(listed):
                failures.append(f"{page} {name} type {label} H{dim}: rows {ids} of {table.get_attribute('data-total')}, "
                                f"medusa classes lists {want} of {len(listed)}")
        # Click the first row of each cell type's loops and cavities, and of the H0 table with the most
        # rows of several cells; the selection must show exactly the class's cells.
        picks = []
        for label in ["1", "2", "all"]:
            for dim in [1, 2, 0]:
                rows = driver.find_elements("css selector",
                                            f".class-row[data-run='{ri}'][data-type='{label}'][data-dim='{dim}']")
                if rows and (dim > 0 or label != "all"):
                    picks.append((label, dim, rows[min(1, len(rows) - 1)] if dim == 0 else rows[0]))
        if shown and os.path.basename(name) == "sorting_3d":
            label, dim, cid = shown
            row = driver.find_elements("css selector",
                                       f".class-row[data-run='{ri}'][data-type='{label}'][data-dim='{dim}'][data-class='{cid}']")
            if not row:
                failures.append(f"{page} {name}: class {cid} of type {label} H{dim} is not in its table")
            else:
                picks.append((label, dim, row[0]))
        if not picks:
            failures.append(f"{page} {name}: no class row to click")
        view = driver.find_element("css selector", f".view3d[data-run='{ri}']")
        for label, dim, row in picks:
            cid = int(row.get_attribute("data-class"))
            driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", row)
            row.click()
            time.sleep(0.2)
            got = driver.execute_script(f"return window.medusaReport.highlighted({ri})")
            want = expected[(label, dim)].get(cid)
            what = f"{page} {name} type {label} H{dim} class {cid}"
            if want is None:
                failures.append(f"{what}: not listed by medusa classes")
                continue
            selected = driver.find_elements("css selector", f".class-row.selected[data-run='{ri}']")
            if len(selected) != 1 or selected[0] != row:
                failures.append(f"{what}: {len(selected)} rows marked selected after the click")
            if (got["type"], got["dim"], got["id"]) != (label, dim, cid):
                failures.append(f"{what}: the view shows {got['type']} H{got['dim']} class {got['id']}")
            if not got["webgl"]:
                failures.append(f"{what}: no WebGL, the 3D view was not drawn")
            if abs(got["time"] - want["birth"]) > 1e-9 * max(1, abs(want["birth"])):
                failures.append(f"{what}: shown at MCS {got['time']}, born at {want['birth']}")
            if sorted(got["cells"]) != want["cells"] or got["absent"]:
                failures.append(f"{what}: highlighted {got['cells']} (absent {got['absent']}), "
                                f"medusa classes: {want['cells']}")
            if got["webgl"]:
                types = set(driver.execute_script(f"return window.medusaReport.types({ri}, arguments[0])", want["cells"]))
                for t in types:
                    if t in TYPE_COLOURS and canvas_has_colour(view, TYPE_COLOURS[t], f"class_{ri}_{cid}.png") < 20:
                        failures.append(f"{what}: no cell drawn in the colour of type {t} in the 3D view")
            clicks += 1
        if screenshot and shown and os.path.basename(name) == "sorting_3d":
            driver.execute_script("arguments[0].scrollIntoView({block: 'start'})", view)
            time.sleep(0.3)
            view.screenshot("class_view.png")
            Image.open("class_view.png").convert("RGB").save(screenshot, optimize=True)
        t_end = driver.execute_script(f"return window.medusaReport.range({ri})[1]")
        fates = check_ring_fates(driver, call, page, name, ri, expected, t_end, failures)
        if fates == 0:
            failures.append(f"{page} {name}: no essential loop or cavity row of a cell type says what became of its ring")
        # Positions between frames: those `medusa at` interpolates.
        t0, t1 = driver.execute_script(f"return [window.medusaReport.range({ri})[0], window.medusaReport.range({ri})[1]]")
        t = t0 + (t1 - t0) * 0.6173
        call("at", store, "--time", repr(t), "-o", f"at_{ri}.vtk")
        at = vtk_positions(f"at_{ri}.vtk")
        page_xyz = driver.execute_script(f"return window.medusaReport.positions({ri}, arguments[0])", t)
        worst = 0.0
        for cid, x in at.items():
            y = page_xyz.get(str(cid))
            if y is None:
                failures.append(f"{page} {name}: CC3D cell {cid} is in medusa at's complex at MCS {t} but not in the view")
                break
            worst = max(worst, max(abs(a - b) for a, b in zip(x, y)))
        if not at or worst > 2e-3:
            failures.append(f"{page} {name}: positions at MCS {t} differ from medusa at by {worst} ({len(at)} points)")
        # The time input moves the view.
        box = view.find_element("css selector", ".class-time-number")
        driver.execute_script("arguments[0].value = arguments[1]; arguments[0].dispatchEvent(new Event('change'))", box, t)
        if abs(driver.execute_script(f"return window.medusaReport.highlighted({ri}).time") - t) > 1e-6:
            failures.append(f"{page} {name}: the time input did not move the view to MCS {t}")
        print(f"{page} {name}: classes section: {len(tables)} tables, {len(picks)} classes clicked, {fates} rings checked, "
              f"positions at MCS {t:.4g} within {worst:.2g} of medusa at ({len(at)} cells)")
    return clicks
