"""Reading the VTK files of the deck (dump polyhedron/vtk, dump wire/vtk, LIGGGHTS' dump
custom/vtk of spheres) with Debian's python3-vtk9; shared by plot_columns.py and
observables.py."""

import os
import re
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOLegacy import vtkGenericDataObjectReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def read_polydata(path):
    """A VTK XML PolyData file (.vtp)."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data.GetNumberOfPoints() == 0:
        sys.exit(f"{os.path.basename(sys.argv[0])}: {path} holds no points (not a VTK XML PolyData file?)")
    return data


def read_legacy_spheres(path):
    """LIGGGHTS' legacy VTK of spheres (dump custom/vtk ... x y z radius): (points, {array: values})."""
    reader = vtkGenericDataObjectReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data is None or not data.GetPoints() or data.GetPointData().GetArray("radius") is None:
        sys.exit(f"{os.path.basename(sys.argv[0])}: {path} holds no points with a radius array")
    arrays = {}
    for k in range(data.GetPointData().GetNumberOfArrays()):
        array = data.GetPointData().GetArray(k)
        arrays[array.GetName()] = vtk_to_numpy(array)
    return vtk_to_numpy(data.GetPoints().GetData()), arrays


def cells(cell_array):
    """A vtkCellArray as a list of point-index arrays."""
    offsets = vtk_to_numpy(cell_array.GetOffsetsArray())
    connectivity = vtk_to_numpy(cell_array.GetConnectivityArray())
    return [connectivity[offsets[k]:offsets[k + 1]] for k in range(len(offsets) - 1)]


def point_array(data, name):
    array = data.GetPointData().GetArray(name)
    return None if array is None else vtk_to_numpy(array)


def cell_array(data, name):
    array = data.GetCellData().GetArray(name)
    return None if array is None else vtk_to_numpy(array)


def wire_beside(grains_path):
    """The wire file the deck writes beside a grains file ("grains" → "wire", .vtp), or None."""
    wire = os.path.join(os.path.dirname(grains_path), os.path.basename(grains_path).replace("grains", "wire"))
    wire = os.path.splitext(wire)[0] + ".vtp"
    return wire if os.path.exists(wire) else None


def step_of(path):
    """The time step in a snapshot's file name (the last group of digits)."""
    found = re.findall(r"\d+", os.path.basename(path))
    return int(found[-1]) if found else 0
