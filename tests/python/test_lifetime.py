"""Simulations made and dropped many times hold no memory: 1000 create-run-destroy cycles."""
import gc

import talus
from conftest import SMALL


def resident_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS in /proc/self/status")


def cycle(scenario):
    sim = talus.Simulation(scenario)
    sim.run(steps=20)
    sim.positions, sim.contacts(), sim.thermo()
    sim.close()


def test_no_leak_over_1000_cycles():
    scenario = talus.scenario(SMALL)
    for _ in range(100):  # the allocator's pools and Python's caches fill first
        cycle(scenario)
    gc.collect()
    before = resident_kib()
    for _ in range(1000):
        cycle(scenario)
    gc.collect()
    grown = resident_kib() - before
    # One engine of this size holds tens of KiB; 1000 of them kept would be tens of MiB. What
    # stays is the allocator's fragmentation, well under 4 MiB.
    assert grown < 4096, f"the process grew by {grown} KiB over 1000 cycles"
