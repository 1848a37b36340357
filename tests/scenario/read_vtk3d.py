"""Loads a 3D run folder's snapshots with VTK's own XML reader (what ParaView uses): every
snapshot of particles.pvd opens with one point per sphere (run.json), inside the box, with the
documented arrays, 3 components for the vectors; every plates snapshot of walls.pvd opens with one
quadrilateral per plate. Exit 77 (skipped) when VTK is not installed."""
import json
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

try:
    import vtk
except ImportError:
    print("python3-vtk9 is not installed: skipping")
    sys.exit(77)

run = Path(sys.argv[1])
facts = json.loads((run / "run.json").read_text())
assert facts["dimension"] == 3, facts


def snapshots(collection):
    entries = ET.parse(run / collection).getroot().find("Collection")
    files = [(float(d.get("timestep")), d.get("file")) for d in entries]
    assert len(files) >= 2, files
    assert all(a[0] < b[0] for a, b in zip(files, files[1:])), "times not increasing"
    for _, name in files:
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(str(run / name))
        reader.Update()
        yield name, reader.GetOutput()


count = 0
for name, data in snapshots("particles.pvd"):
    assert data.GetNumberOfPoints() == facts["particles"], (name, data.GetNumberOfPoints())
    assert data.GetNumberOfVerts() == facts["particles"], name
    points = data.GetPointData()
    for array, components in [("id", 1), ("radius", 1), ("velocity", 3), ("angular_velocity", 3),
                              ("force", 3), ("kind", 1), ("material", 1), ("mass", 1)]:
        assert points.GetArray(array) is not None, (name, array)
        assert points.GetArray(array).GetNumberOfComponents() == components, (name, array)
    lo, hi = [0.0, 0.0, 0.0], [float(x) for x in sys.argv[2].split(",")]
    for k in range(data.GetNumberOfPoints()):
        p = data.GetPoint(k)
        assert all(lo[a] - 1e-3 <= p[a] <= hi[a] + 1e-3 for a in range(3)), (name, k, p)
    count += 1
for name, data in snapshots("walls.pvd"):
    assert data.GetNumberOfPolys() == facts["plates"], (name, data.GetNumberOfPolys())
    assert data.GetCellData().GetArray("force") is not None, name
print(f"read {count} snapshots of {facts['particles']} spheres and their plates")
