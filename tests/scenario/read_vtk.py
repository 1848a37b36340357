"""Loads a run folder's snapshots with VTK's own XML reader (what ParaView uses for .vtp files)
and checks what a user would look at: every snapshot listed in particles.pvd opens, has one point
per particle and carries the documented arrays. Exit 77 (skipped) when VTK is not installed."""
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
particles = json.loads((run / "run.json").read_text())["particles"]
entries = ET.parse(run / "particles.pvd").getroot().find("Collection")
files = [(float(d.get("timestep")), d.get("file")) for d in entries]
assert len(files) >= 2, files
assert all(a[0] < b[0] for a, b in zip(files, files[1:])), "times not increasing"
for _, name in files:
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(run / name))
    reader.Update()
    data = reader.GetOutput()
    assert data.GetNumberOfPoints() == particles, (name, data.GetNumberOfPoints(), particles)
    assert data.GetNumberOfVerts() == particles, name
    point_data = data.GetPointData()
    for array in ["id", "radius", "velocity", "angular_velocity", "force", "kind", "material"]:
        assert point_data.GetArray(array) is not None, (name, array)
    assert point_data.GetArray("velocity").GetNumberOfComponents() == 3
print(f"read {len(files)} snapshots of {particles} particles with VTK {vtk.vtkVersion.GetVTKVersion()}")

# the walls and the contacts (force chains) open too, with their cell arrays
for collection, arrays in [("walls.pvd", ["force"]),
                           ("contacts.pvd", ["normal_force", "tangential_force", "particle", "partner"])]:
    if not (run / collection).exists():
        continue
    for d in ET.parse(run / collection).getroot().find("Collection"):
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(str(run / d.get("file")))
        reader.Update()
        data = reader.GetOutput()
        assert data.GetNumberOfPoints() == 2 * data.GetNumberOfLines(), d.get("file")
        for array in arrays:
            assert data.GetCellData().GetArray(array) is not None, (d.get("file"), array)
print("walls and contacts read too")
