# Reads pdq ParaView series with ParaView's own readers and prints what the test checks.
# Usage: pvpython read_vtu.py PARTICLES.pvd POINTFIELDS BONDS.pvd CELLFIELDS
# (FIELDS: one array name, or several separated by commas)
# For each series:
#   series <file>
#   times <t0> <t1> ...          its time steps
#   points <n> cells <m>         at the last time step
#   value <id> <values>          particles: per point, every component of the fields
#   value <id> <id> <values>     bonds: per cell (its ends' IDs, smaller first)
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


def components(arrays, k):
    return " ".join(repr(a.GetComponent(k, c)) for a in arrays
                    for c in range(a.GetNumberOfComponents()))


data = last_step(sys.argv[1])
ids = data.GetPointData().GetArray("id")
values = [data.GetPointData().GetArray(n) for n in sys.argv[2].split(",")]
for i in range(data.GetNumberOfPoints()):
    print("value", int(ids.GetValue(i)), components(values, i))

data = last_step(sys.argv[3])
ids = data.GetPointData().GetArray("id")
values = [data.GetCellData().GetArray(n) for n in sys.argv[4].split(",")]
for c in range(data.GetNumberOfCells()):
    cell = data.GetCell(c)
    a, b = (int(ids.GetValue(cell.GetPointId(k))) for k in range(2))
    print("value", min(a, b), max(a, b), components(values, c))
