"""Loads a 3D scene's .vtp files with VTK's own XML reader (what ParaView uses) and checks them
against the numbers the test wrote beside them: one point per sphere at its position, the
documented arrays, the box in the field data, one line per contact, one quadrilateral per plate. Exit 77 (skipped) when VTK is not installed."""
import json
import sys
from pathlib import Path

try:
    import vtk
except ImportError:
    print("python3-vtk9 is not installed: skipping")
    sys.exit(77)

folder = Path(sys.argv[1])
expected = json.loads((folder / "expected.json").read_text())


def read(name):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(folder / name))
    reader.Update()
    return reader.GetOutput()


spheres = read("spheres.vtp")
assert spheres.GetNumberOfPoints() == len(expected["positions"]), spheres.GetNumberOfPoints()
assert spheres.GetNumberOfVerts() == len(expected["positions"])
for k, position in enumerate(expected["positions"]):
    got = spheres.GetPoint(k)
    assert all(abs(a - b) <= 1e-11 for a, b in zip(got, position)), (k, got, position)
data = spheres.GetPointData()
for name, components in [("id", 1), ("radius", 1), ("velocity", 3), ("angular_velocity", 3),
                         ("force", 3), ("kind", 1), ("material", 1), ("mass", 1)]:
    array = data.GetArray(name)
    assert array is not None, name
    assert array.GetNumberOfComponents() == components, (name, array.GetNumberOfComponents())
spin = data.GetArray("angular_velocity").GetTuple3(0)
assert all(abs(a - b) <= 1e-8 * max(1.0, abs(b)) for a, b in zip(spin, expected["spin0"])), spin

box = spheres.GetFieldData().GetArray("box")
assert box is not None and box.GetNumberOfComponents() == 6
assert list(box.GetTuple(0)) == expected["box"], box.GetTuple(0)
assert spheres.GetFieldData().GetArray("periodic").GetNumberOfComponents() == 3
assert spheres.GetFieldData().GetArray("shear_velocity") is not None

contacts = read("contacts.vtp")
assert expected["contacts"] > 0
assert contacts.GetNumberOfLines() == expected["contacts"], contacts.GetNumberOfLines()
for name, components in [("normal_force", 1), ("tangential_force", 1), ("overlap", 1),
                         ("contact_point", 3), ("force", 3), ("particle", 1), ("partner", 1)]:
    array = contacts.GetCellData().GetArray(name)
    assert array is not None, name
    assert array.GetNumberOfComponents() == components, (name, array.GetNumberOfComponents())

plates = read("plates.vtp")
assert plates.GetNumberOfPolys() == expected["plates"], plates.GetNumberOfPolys()
assert plates.GetNumberOfPoints() == 4 * expected["plates"]
assert plates.GetCellData().GetArray("force") is not None
print("ok")
