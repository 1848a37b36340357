#!/usr/bin/python3
"""Every example of the styles' doc page (lammps-package/README.md) runs as written: each indented
block under a style's "Examples" or "pair_style hybrid" heading, after a 2d box of two atom types
(a pair of touching type-1 disks in the group `grains`, a type-2 disk apart), then `run 10`. The
block's own box set-up lines (dimension, units, atom_style) go before the box; a block with
`dimension 3` gets a 3d box of spheres instead. A block without a pair style gets `pair_style
granthesis linear coulomb` with every type's defaults.

Usage: doc_examples_test.py TALUS_LMP README WORK_DIR"""
import os
import re
import subprocess
import sys

STYLES = ("## pair_style granthesis", "## fix granthesis/wall", "## fix frost/heave")
RUNNABLE = ("### Examples", "### pair_style hybrid")
BEFORE_BOX = ("dimension", "units", "atom_style", "atom_modify")


def example_blocks(text):
    """The runnable blocks: (heading, [lines])."""
    blocks, section, heading, block = [], "", "", None
    for line in text.splitlines() + [""]:
        if line.startswith("## "):
            section = line
        if line.startswith("### "):
            heading = line
        runnable = section in STYLES and heading in RUNNABLE
        if runnable and line.startswith("    "):
            if block is None:
                block = (f"{section} / {heading}", [])
                blocks.append(block)
            block[1].append(line.strip())
        else:  # a blank or text line ends a block
            block = None
    return blocks


def deck_of(lines):
    setup = [l for l in lines if l.split()[0] in BEFORE_BOX]
    body = [l for l in lines if l.split()[0] not in BEFORE_BOX]
    words = {l.split()[0] for l in setup}
    spheres = "dimension 3" in setup
    defaults = [d for d in ("dimension 2", "units si", "atom_style sphere")
                if d.split()[0] not in words]
    deck = defaults + setup + [
        "boundary f f f" if spheres else "boundary f f p", "comm_modify vel yes",
        "region box block -0.2 0.4 -0.1 0.5 " + ("-0.2 0.2" if spheres else "-0.01 0.01"),
        "create_box 2 box",
        "create_atoms 1 single 0 0.02 0", "create_atoms 1 single 0.0095 0.02 0",
        "create_atoms 2 single 0.1 0.1 0", "set atom * diameter 0.01",
        "set atom * density 2650" if spheres else "set atom * density/disc 2650",
        "group grains type 1"]
    if not any(l.startswith("pair_style") for l in body):
        deck += ["pair_style granthesis linear coulomb", "pair_coeff * *"]
    deck += body
    if not any(re.match(r"fix \S+ \S+ nve", l) for l in body):
        deck.append("fix move all nve/sphere" if spheres else "fix move all nve/sphere disc")
    return deck + ["timestep 1e-5", "run 10"]


def main():
    launcher, readme, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    with open(readme) as f:
        blocks = example_blocks(f.read())
    if len(blocks) < 5:
        sys.exit(f"found {len(blocks)} example blocks in {readme}: the page's headings changed?")
    failed = 0
    for k, (where, lines) in enumerate(blocks):
        path = os.path.join(work, f"example_{k}.in")
        with open(path, "w") as f:
            f.write("\n".join(deck_of(lines)) + "\n")
        done = subprocess.run([launcher, "-in", path, "-log", "none"], capture_output=True,
                              text=True, timeout=120)
        printed = done.stdout + done.stderr
        ok = done.returncode == 0 and "ERROR" not in printed and "WARNING" not in printed
        print(f"{'ran' if ok else 'FAILED'}: {where}: {lines[0]} ... ({len(lines)} lines)")
        if not ok:
            failed += 1
            print(printed[-3000:])
    if failed:
        sys.exit(f"{failed} of {len(blocks)} examples failed")


if __name__ == "__main__":
    main()
