"""In-process compose time of both sheets (en), median of 5, wall and CPU seconds.

Compare two trees in one run (a busy machine: read the ratio, not the seconds):

    for t in /path/to/base /path/to/new; do
        PYTHONPATH=$t MMT_PLANS_TEMPLATES=$t/templates python bench/compose_times.py \
            samples/six_link_press.toml samples/shaper.toml
    done
"""

import statistics
import sys
import time

from mmt_plans import load, solve
from mmt_plans.sheets.compose import compose

for f in sys.argv[1:]:
    sol = solve(load(f))
    compose(sol, "en", (1, 2))
    wall, cpu = [], []
    for _ in range(5):
        t, p = time.perf_counter(), time.process_time()
        compose(sol, "en", (1, 2))
        wall.append(time.perf_counter() - t)
        cpu.append(time.process_time() - p)
    name = f.split("/")[-1]
    print(f"{name:36s} wall {statistics.median(wall):.3f}  cpu {statistics.median(cpu):.3f}")
