"""The radius sweep as `medusa sweep` writes it and as `medusa report` embeds it in its page, both as
{(radius as Decimal, time, type label): [b0, b1, b2]}, for the checks that compare the two."""
import csv
import json
import re
from decimal import Decimal


def page_data(path):
    """The JSON a report page carries (script#report-data)."""
    text = open(path).read()
    m = re.search(r'<script type="application/json" id="report-data">(.*?)</script>', text, re.S)
    return json.loads(m.group(1).replace("<\\/", "</"))


def sweep_csv(path):
    """A `medusa sweep` CROCKER CSV."""
    with open(path) as f:
        return {(Decimal(r["radius"]), float(r["time"]), r["type"]): [int(r["b0"]), int(r["b1"]), int(r["b2"])]
                for r in csv.DictReader(f)}


def page_sweep(sweep):
    """The same mapping from one sweep of the page's JSON."""
    out = {}
    for t in sweep["types"]:
        for ri, radius in enumerate(sweep["radii"]):
            for k, time in enumerate(sweep["times"]):
                out[(Decimal(radius), float(time), t["label"])] = t["betti"][ri][k]
    return out
