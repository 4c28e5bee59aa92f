"""What reading the input warned of is recorded, and said wherever the run's results are read (run with
/usr/bin/python3; PYTHONPATH must hold the medusa module).

usage: check_input_warnings.py <medusa> <cut-short run folder> <complete cells.csv.gz> <workdir>

The cut-short folder's cells.csv.gz stops at MCS 300 while its CC3DML runs to MCS 2000. Checks that:
* `medusa run` prints one warning line, and the store's `input_warnings` attribute holds exactly that
  line (docs/FORMAT.md); under -q nothing is printed and the same line is still recorded;
* `medusa info` lists it under "input warnings: 1";
* `medusa report` carries it in the page's data, in its plain-HTML verdicts (JavaScript off) and, in
  headless Chromium, on the run's card beside the verdict and in its facts table;
* `medusa.run` gives it as a Python UserWarning and `Store.input_warnings` holds it;
* a complete run records no warning: info says "input warnings: 0", the card shows none.
"""
import html
import os
import shutil
import subprocess
import sys
import warnings

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_sweep_data import page_data  # noqa: E402

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")

medusa_exe, cut_run, complete_csv, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)


def run(*args):
    print("$", " ".join(args))
    result = subprocess.run(args, cwd=work, capture_output=True, text=True)
    print(result.stdout[-2000:], result.stderr, sep="\n")
    assert result.returncode == 0, result.returncode
    return result


def recorded(store):
    with h5py.File(os.path.join(work, store), "r") as f:
        return [s.decode() for s in f.attrs["input_warnings"]]


# medusa run: one line on stderr, the same line in the store.
result = run(medusa_exe, "run", cut_run, "-o", "cut.h5")
printed = [line[len("medusa: warning: "):] for line in result.stderr.splitlines()
           if line.startswith("medusa: warning: ")]
assert len(printed) == 1 and "the analysis covers MCS 0 to 300 only" in printed[0], printed
assert recorded("cut.h5") == printed, (recorded("cut.h5"), printed)
warning = printed[0]

quiet = run(medusa_exe, "run", cut_run, "-o", "quiet.h5", "-q")
assert "warning" not in quiet.stderr, quiet.stderr
assert recorded("quiet.h5") == [warning]

# medusa info.
info = run(medusa_exe, "info", "cut.h5").stdout.splitlines()
at = info.index("input warnings: 1")
assert info[at + 1] == "  " + warning, info[at + 1]

# A complete run: nothing recorded, nothing said.
run(medusa_exe, "run", complete_csv, "-o", "complete.h5")
assert recorded("complete.h5") == []
assert "input warnings: 0" in run(medusa_exe, "info", "complete.h5").stdout.splitlines()

# medusa report: the page's data and its plain-HTML verdicts.
run(medusa_exe, "report", "cut.h5", "complete.h5", "-o", "report.html", "--no-sweep", "-q")
page = os.path.join(work, "report.html")
data = page_data(page)
assert [r["facts"]["input_warnings"] for r in data["runs"]] == [[warning], []]
text = open(page).read()
noscript = text[text.index("<noscript>"):text.index("</noscript>")]
assert noscript.count('class="input-warning"') == 1, noscript
assert "<b>Input warning: </b>" + html.escape(warning, quote=False) in noscript, noscript

# The page in a browser: the card of the cut-short run says it beside its verdict, the other's does not.
from selenium import webdriver  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402

options = webdriver.ChromeOptions()
for a in ["--headless=new", "--no-sandbox", "--window-size=1300,1000"]:
    options.add_argument(a)
driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
try:
    driver.get("file://" + page)
    cards = driver.find_elements(By.CSS_SELECTOR, "#headlines .run-card")
    assert len(cards) == 2, len(cards)
    shown = [[p.text for p in c.find_elements(By.CSS_SELECTOR, "p.input-warning")] for c in cards]
    assert shown == [["Input warning: " + warning], []], shown
    verdict = cards[0].find_element(By.CSS_SELECTOR, "p.verdict")
    below = cards[0].find_element(By.CSS_SELECTOR, "p.verdict + p.input-warning")
    assert below.location["y"] > verdict.location["y"]
    rows = {}
    for section in driver.find_elements(By.CSS_SELECTOR, "#details section.run"):
        for tr in section.find_elements(By.CSS_SELECTOR, "table.facts tr"):
            cells = tr.find_elements(By.TAG_NAME, "td")
            if cells[0].text == "input warnings":
                rows.setdefault("input warnings", []).append(cells[1].text)
    assert rows["input warnings"] == [warning, "none"], rows
finally:
    driver.quit()

# The Python module: a UserWarning, and the store's property.
import medusa  # noqa: E402

with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    store = medusa.run(cut_run, output=os.path.join(work, "python.h5"))
said = [str(w.message) for w in caught if issubclass(w.category, UserWarning)]
assert said == [warning], said
assert store.input_warnings == [warning]
assert medusa.open(os.path.join(work, "complete.h5")).input_warnings == []

print("input warnings recorded and shown:", warning)
