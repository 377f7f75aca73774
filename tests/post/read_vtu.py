# Reads a pdq ParaView series with ParaView's own readers and prints what the test checks:
#   times <t0> <t1> ...          the series' time steps
#   points <n> cells <m>         at the last time step
#   value <id> <field value>     one line per point (the field's first component)
# Usage: pvpython read_vtu.py SERIES.pvd FIELD [point|cell]
import sys

from paraview import servermanager
from paraview.simple import PVDReader

path, field = sys.argv[1], sys.argv[2]
where = sys.argv[3] if len(sys.argv) > 3 else "point"
reader = PVDReader(FileName=path)
times = list(reader.TimestepValues)
print("times", " ".join(repr(t) for t in times))
reader.UpdatePipeline(times[-1])
data = servermanager.Fetch(reader)
print("points", data.GetNumberOfPoints(), "cells", data.GetNumberOfCells())
attrs = data.GetPointData() if where == "point" else data.GetCellData()
values = attrs.GetArray(field)
ids = data.GetPointData().GetArray("id")
if where == "point":
    for i in range(data.GetNumberOfPoints()):
        print("value", int(ids.GetValue(i)), repr(values.GetComponent(i, 0)))
else:
    # A bond is named by its two ends' IDs, smaller first.
    for c in range(data.GetNumberOfCells()):
        cell = data.GetCell(c)
        a, b = (int(ids.GetValue(cell.GetPointId(k))) for k in range(2))
        print("value", min(a, b), max(a, b), repr(values.GetComponent(c, 0)))
