"""Snapshots of both engines in the one layout `talus analyze` reads.

A LAMMPS run of an exported deck, given the dumps `analysis_dumps` adds, becomes a talus run
folder (particles.pvd, contacts.pvd and their .vtp files, the native scenario.toml, and frost.csv
from `fix frost/heave`'s heaves in log.lammps), so that the native analyses (`talus analyze DIR
forces`, `segregation`, `profiles`, `frost`, ...) measure both engines with the same code.
`read_frames` reads the particles of either folder back into arrays.
"""
import os
import re
import shutil
import tomllib

import numpy as np

# Appended to an exported deck before its `run`: every grain's state, and every pair within the
# force cutoff with its distance, normal force F_n (granthesis' p5), overlap (p6) and the
# contact's force on the first atom (p1, p2: normal and tangential together, for stresses). The
# two local computes walk the same neighbour list with the same cutoff, so their rows match.
ANALYSIS_DUMPS = """\
compute talus_pair_ids all property/local patom1 patom2
compute talus_pair_forces all pair/local dist p5 p6 p1 p2
dump talus_frames all custom ${analysis_every} dump.frames id type radius mass x y vx vy fx fy &
  omegaz
dump_modify talus_frames sort id format float %.17g
dump talus_contacts all local ${analysis_every} dump.contacts c_talus_pair_ids[1] &
  c_talus_pair_ids[2] c_talus_pair_forces[1] c_talus_pair_forces[2] c_talus_pair_forces[3] &
  c_talus_pair_forces[4] c_talus_pair_forces[5]
dump_modify talus_contacts format float %.17g
"""


# Where the deck has wall segments (the export's `fix walls ... granthesis/wall`): each wall
# contact with the atom, the segment (from 1), F_n, the overlap and the point on the segment.
WALL_DUMP = """\
dump talus_walls all local ${analysis_every} dump.walls f_walls[1] f_walls[2] f_walls[3] &
  f_walls[4] f_walls[5] f_walls[6]
dump_modify talus_walls format float %.17g
"""


def add_analysis_dumps(deck):
    """Puts ANALYSIS_DUMPS (and WALL_DUMP where there are wall segments) before the deck's `run`
    line."""
    with open(deck) as f:
        lines = f.read().splitlines(keepends=True)
    at = next(k for k, line in enumerate(lines) if line.startswith("run "))
    walls = any(line.startswith("fix walls ") and "granthesis/wall" in line for line in lines)
    lines.insert(at, ANALYSIS_DUMPS + (WALL_DUMP if walls else ""))
    with open(deck, "w") as f:
        f.writelines(lines)


def dump_blocks(path):
    """(timestep, column names, rows as a float array) for each block of a LAMMPS text dump."""
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        step, count = int(lines[k + 1]), int(lines[k + 3])
        columns = lines[k + 8].split()[2:]
        body = lines[k + 9:k + 9 + count]
        rows = (np.array(" ".join(body).split(), dtype=float).reshape(count, -1)
                if count else np.zeros((0, len(columns))))
        yield step, columns, rows
        k += 9 + count


def data_array(xml, name, path):
    """The numbers of a talus .vtp's DataArray called `name`."""
    match = re.search(r'<DataArray[^>]*Name="' + re.escape(name) + r'"[^>]*>(.*?)</DataArray>',
                      xml, re.S)
    if match is None:
        raise ValueError(f"{path}: no DataArray '{name}' (not a talus snapshot?)")
    return np.array(match.group(1).split(), dtype=float)


def pvd_entries(path):
    """(time, file relative to the folder) of a .pvd collection."""
    with open(path) as f:
        xml = f.read()
    return [(float(t), name) for t, name in
            re.findall(r'<DataSet timestep="([^"]+)"[^>]*file="([^"]+)"', xml)]


def read_frame(path):
    """{id, radius, x, y, vx, vy, kind, material} arrays of one particles_*.vtp."""
    with open(path) as f:
        xml = f.read()
    pos = data_array(xml, "position", path).reshape(-1, 3)
    vel = data_array(xml, "velocity", path).reshape(-1, 3)
    return {"id": data_array(xml, "id", path).astype(int),
            "radius": data_array(xml, "radius", path),
            "x": pos[:, 0], "y": pos[:, 1], "vx": vel[:, 0], "vy": vel[:, 1],
            "kind": data_array(xml, "kind", path).astype(int),
            "material": data_array(xml, "material", path).astype(int)}


def read_frames(folder):
    """[(time, read_frame's arrays)] of a talus run folder."""
    return [(t, read_frame(os.path.join(folder, name)))
            for t, name in pvd_entries(os.path.join(folder, "particles.pvd"))]


def first_frame(folder):
    """read_frame's arrays of a talus run folder's first snapshot, without reading the rest."""
    _, name = pvd_entries(os.path.join(folder, "particles.pvd"))[0]
    return read_frame(os.path.join(folder, name))


def array(name, components, values, fmt="{:.17g}"):
    body = "\n".join(" ".join(fmt.format(v) for v in np.atleast_1d(row)) for row in values)
    return (f'        <DataArray type="Float64" Name="{name}" NumberOfComponents="{components}" '
            f'format="ascii">\n{body}\n        </DataArray>\n')


def polydata(points, cells, point_data, cell_data):
    """A VTK XML PolyData of `points` with verts (cells = 1) or lines (cells = 2)."""
    n = len(points) // cells
    tag = "Verts" if cells == 1 else "Lines"
    out = ['<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" '
           'byte_order="LittleEndian">\n  <PolyData>\n',
           f'    <Piece NumberOfPoints="{len(points)}" NumberOf{tag}="{n}">\n']
    for section, data in (("PointData", point_data), ("CellData", cell_data)):
        out.append(f"      <{section}>\n")
        out += [array(name, comps, values) for name, comps, values in data]
        out.append(f"      </{section}>\n")
    xyz = np.column_stack([points, np.zeros(len(points))])
    out += ["      <Points>\n", array("position", 3, xyz), "      </Points>\n",
            f"      <{tag}>\n",
            '        <DataArray type="Int64" Name="connectivity" format="ascii">\n',
            "\n".join(str(k) for k in range(len(points))), "\n        </DataArray>\n",
            '        <DataArray type="Int64" Name="offsets" format="ascii">\n',
            "\n".join(str(cells * (k + 1)) for k in range(n)), "\n        </DataArray>\n",
            f"      </{tag}>\n    </Piece>\n  </PolyData>\n</VTKFile>\n"]
    return "".join(out)


def pvd(entries):
    rows = "".join(f'    <DataSet timestep="{t!r}" part="0" file="{name}"/>\n'
                   for t, name in entries)
    return ('<?xml version="1.0"?>\n<VTKFile type="Collection" version="1.0">\n'
            f"  <Collection>\n{rows}  </Collection>\n</VTKFile>\n")


def pair_contacts(lammps_dir, step, pairs_block, frame, kind, period):
    """The touching pairs of dump.contacts at `step` as (id, partner id, F_n, overlap, centre,
    partner's centre (its periodic image), the force on the first, the contact point), without
    those of two wall particles (the native engine never forms them); the distance pair/local
    saw must be that of the atoms dumped. `period`: the box's length along x and y where it is
    periodic, else None; frame: the dumped atoms' (xy, radius, row by id)."""
    xy, radius, at = frame
    columns, pairs = pairs_block
    p = {n: pairs[:, i] for i, n in enumerate(columns)}
    found = []
    for r in range(len(pairs)):
        a, b = int(p["c_talus_pair_ids[1]"][r]), int(p["c_talus_pair_ids[2]"][r])
        if p["c_talus_pair_forces[3]"][r] <= 0.0 or (kind[a] != 0 and kind[b] != 0):
            continue
        delta = xy[at[a]] - xy[at[b]]
        for axis, length in enumerate(period):
            if length is not None:
                delta[axis] -= length * round(delta[axis] / length)
        d = np.hypot(*delta)
        if abs(d - p["c_talus_pair_forces[1]"][r]) > 1e-9 * d:
            raise ValueError(f"{lammps_dir}: dump.contacts at step {step} does not match "
                             "dump.frames")
        overlap = p["c_talus_pair_forces[3]"][r]
        # the native contact point: the middle of the overlap, on the line of centres
        point = xy[at[a]] - (radius[at[a]] - 0.5 * overlap) * delta / d
        force = np.array([p["c_talus_pair_forces[4]"][r], p["c_talus_pair_forces[5]"][r]])
        found.append((a, b, p["c_talus_pair_forces[2]"][r], overlap, xy[at[a]],
                      xy[at[a]] - delta, force, point))
    return found


def wall_contacts(walls_block, xy, at):
    """The wall contacts of dump.walls (fix granthesis/wall's local array) as pair_contacts has
    them, the partner numbered as the native engine numbers a segment: -1 - its index."""
    _, rows = walls_block
    return [(int(a), -int(s), force, overlap, xy[at[int(a)]], np.array([px, py]), None, None)
            for a, s, force, overlap, px, py in rows]


def write_contacts(path, found):
    """A contacts .vtp of pair_contacts' rows, ids from 0 as the native engine's; with the
    force vectors and contact points where every row has them (a wall segment's contacts, from
    fix granthesis/wall, have their normal force only)."""
    ends = np.array([end for row in found for end in (row[4], row[5])]).reshape(-1, 2)
    arrays = [("normal_force", 1, [row[2] for row in found]),
              ("overlap", 1, [row[3] for row in found])]
    if all(row[6] is not None for row in found):
        zero = np.zeros((len(found), 1))
        arrays += [("contact_point", 3, np.hstack([np.array([row[7] for row in found]).reshape(
                        -1, 2), zero])),
                   ("force", 3, np.hstack([np.array([row[6] for row in found]).reshape(-1, 2),
                                           zero]))]
    arrays += [("particle", 1, [row[0] - 1 for row in found]),
               ("partner", 1, [row[1] - 1 if row[1] > 0 else row[1] for row in found])]
    with open(path, "w") as f:
        f.write(polydata(ends, 2, [], arrays))


def lammps_run_folder(lammps_dir, native_folder, dt, out):
    """Writes `out`, a talus run folder of the LAMMPS run in `lammps_dir` (its dump.frames and
    dump.contacts, and dump.walls where there are wall segments): the native run's scenario, and
    its kinds and materials by id (LAMMPS ids are the native ids + 1; a grain's kind and
    material never change)."""
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(os.path.join(out, "snapshots"))
    shutil.copy(os.path.join(native_folder, "scenario.toml"), out)
    with open(os.path.join(native_folder, "scenario.toml"), "rb") as f:
        geometry = tomllib.load(f).get("geometry", {})
    box, periodic = geometry.get("box"), geometry.get("periodic", "none")
    period = [box[2] - box[0] if box and axis in periodic else None for axis in "xy"]
    first = first_frame(native_folder)
    kind = dict(zip(first["id"] + 1, first["kind"]))
    material = dict(zip(first["id"] + 1, first["material"]))
    frames = list(dump_blocks(os.path.join(lammps_dir, "dump.frames")))
    contacts = {step: (columns, rows) for step, columns, rows in
                dump_blocks(os.path.join(lammps_dir, "dump.contacts"))}
    walls_path = os.path.join(lammps_dir, "dump.walls")
    walls = ({step: (columns, rows) for step, columns, rows in dump_blocks(walls_path)}
             if os.path.exists(walls_path) else {})
    particles_pvd, contacts_pvd = [], []
    for k, (step, columns, rows) in enumerate(frames):
        c = {name: rows[:, i] for i, name in enumerate(columns)}
        ids = c["id"].astype(int)
        at = {i: n for n, i in enumerate(ids)}
        xy = np.column_stack([c["x"], c["y"]])
        zero = np.zeros(len(ids))
        name = f"snapshots/particles_{k:06d}.vtp"
        with open(os.path.join(out, name), "w") as f:
            f.write(polydata(xy, 1, [
                ("id", 1, ids - 1), ("radius", 1, c["radius"]), ("mass", 1, c["mass"]),
                ("velocity", 3, np.column_stack([c["vx"], c["vy"], zero])),
                ("angular_velocity", 1, c["omegaz"]),
                ("force", 3, np.column_stack([c["fx"], c["fy"], zero])),
                ("kind", 1, [kind[i] for i in ids]),
                ("material", 1, [material[i] for i in ids])], []))
        particles_pvd.append((step * dt, name))
        found = pair_contacts(lammps_dir, step, contacts[step], (xy, c["radius"], at), kind,
                              period)
        if step in walls:
            found += wall_contacts(walls[step], xy, at)
        name = f"snapshots/contacts_{k:06d}.vtp"
        write_contacts(os.path.join(out, name), found)
        contacts_pvd.append((step * dt, name))
    with open(os.path.join(out, "particles.pvd"), "w") as f:
        f.write(pvd(particles_pvd))
    with open(os.path.join(out, "contacts.pvd"), "w") as f:
        f.write(pvd(contacts_pvd))
    heaves = frost_heaves(os.path.join(lammps_dir, "log.lammps"))
    if heaves:
        # the native frost.csv's layout and digits: `talus analyze DIR frost` samples the bed
        # at rest before each freeze
        with open(os.path.join(out, "frost.csv"), "w") as f:
            f.write("cycle,time,event\n" + "".join(
                f"{n},{t:.9g},freeze\n" for n, t in heaves))
    return out


HEAVE = re.compile(r"^(?:fix )?frost/heave: heave (\d+) at t = (\S+) s \(step \d+\)$")


def frost_heaves(log):
    """(number, time) of each heave `fix frost/heave` wrote to a LAMMPS log; [] if none."""
    if not os.path.exists(log):
        return []
    with open(log) as f:
        return [(int(m[1]), float(m[2])) for m in map(HEAVE.match, f) if m]
