# Reads pdq ParaView series with ParaView's own readers and prints what the test checks.
# Usage: pvpython read_vtu.py PARTICLES.pvd POINTFIELD BONDS.pvd CELLFIELD
# For each series:
#   series <file>
#   times <t0> <t1> ...          its time steps
#   points <n> cells <m>         at the last time step
#   value <id> <value>           particles: per point, the field's first component
#   value <id> <id> <value>      bonds: per cell (its ends' IDs, smaller first)
import sys

from paraview import servermanager
from paraview.simple import PVDReader


def last_step(path):
    reader = PVDReader(FileName=path)
    times = list(reader.TimestepValues)
    print("series", path)
    print("times", " ".join(repr(t) for t in times))
    reader.UpdatePipeline(times[-1])
    data = servermanager.Fetch(reader)
    print("points", data.GetNumberOfPoints(), "cells", data.GetNumberOfCells())
    return data


data = last_step(sys.argv[1])
ids = data.GetPointData().GetArray("id")
values = data.GetPointData().GetArray(sys.argv[2])
for i in range(data.GetNumberOfPoints()):
    print("value", int(ids.GetValue(i)), repr(values.GetComponent(i, 0)))

data = last_step(sys.argv[3])
ids = data.GetPointData().GetArray("id")
values = data.GetCellData().GetArray(sys.argv[4])
for c in range(data.GetNumberOfCells()):
    cell = data.GetCell(c)
    a, b = (int(ids.GetValue(cell.GetPointId(k))) for k in range(2))
    print("value", min(a, b), max(a, b), repr(values.GetComponent(c, 0)))
