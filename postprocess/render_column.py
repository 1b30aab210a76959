#!/usr/bin/python3
"""Render a column to a PNG with VTK (the paper's Figs. 6 and 12): the grains as their
polyhedra, the wire as a tube coloured by its elastic strain energy per bead, with a colour
bar; one state, or two side by side (e.g. before and after the wall removal).

    postprocess/render_column.py --grains post/grains_final_40000.vtp [--wire FILE.vtp] --out column.png
    postprocess/render_column.py --series post [--frame K | --frame t=T] --out column.png
    postprocess/render_column.py --before post/grains_relaxed_20000.vtp --after post/grains_final_40000.vtp \\
        --titles "walls in place" "walls removed" --out removal.png
    options: [--size W H] [--view elevated|side|top] [--elevation DEG] [--azimuth DEG]
             [--layout auto|row|column] [--energy-range MIN MAX] [--tube-radius 0.1]
             [--floor Z|none] [--title TEXT] [--no-wire]

Input: the files of `dump polyhedron/vtk` (grains) and `dump wire/vtk ... energy elastic`
(wire). A STATE (--series, --before, --after) is
  - a grains .vtp file: the wire is the file beside it with "grains" replaced by "wire" in
    its name (as input_scripts/in.column writes post/grains_final_STEP.vtp and
    post/wire_final_STEP.vtp), or --wire;
  - a directory holding grains.vtp.series (and wire.vtp.series), or a run directory whose
    post/ holds them (a deck with `dump ... post/grains_*.vtp`), or a grains .vtp.series
    file: the last frame, or --frame K (index into the series, negative from the end) or
    --frame t=T (the frame nearest time T); the wire frame is the one nearest the grains'
    time. With --before and --after, a frame may follow the path: --before post 0.
Output: a PNG of --size W H pixels (default 1200 900, both panels together). Views:
elevated (default: elevation 20 deg, azimuth 30 deg), side (horizontal, looking along +y),
top; --elevation and --azimuth override. Parallel projection; two panels share one scale
and one energy range, so they compare, and stand side by side (--layout row) or one above
the other (column; auto, the default, takes the one that draws the column larger). The
colour scale runs from 0 to the 99th percentile of the bead energies shown (the few beads
above it take the top colour) or over --energy-range. Titles: the state's time (or step),
or --title / --titles. The wire's radius is not in the files: --tube-radius (default 0.1,
Table 1's r_w). A floor is drawn at z = 0 (--floor).

Runs without a display: Debian's VTK (python3-vtk9) renders through X only, so when DISPLAY
is unset the script starts its own X server in memory (Xvfb, Debian package xvfb, in
build.sh's package list) for the run and stops it at the end. Uses python3-vtk9 and numpy."""

import argparse
import json
import os
import subprocess
import sys

import numpy as np

from vtk_files import read_polydata, step_of, wire_beside

# matplotlib's "plasma" at 0, 1/8, ..., 7/8 (its last, pale yellow, eighth left out: it
# vanishes on white)
PLASMA = [(0.0504, 0.0298, 0.528), (0.2999, 0.0096, 0.6316), (0.4949, 0.012, 0.6579), (0.6651, 0.1386, 0.5856),
          (0.7982, 0.2802, 0.4695), (0.9018, 0.4251, 0.3597), (0.9734, 0.5858, 0.2515), (0.993, 0.7717, 0.1548)]
GRAIN_RGB = np.array([0.86, 0.81, 0.72])   # sand; each grain a shade of it
WIRE_RGB = (0.15, 0.25, 0.6)               # a wire written without energies
VIEWS = {"elevated": (20.0, 30.0), "side": (0.0, 0.0), "top": (90.0, 0.0)}
ENERGY = "elastic_energy"


class State:
    """One picture: the grains and wire files and a title."""

    def __init__(self, grains, wire, label):
        self.grains, self.wire, self.label = grains, wire, label


def fail(message):
    sys.exit(f"render_column.py: {message}")


def read_series(path):
    """A .vtp.series file as [(absolute file, time)] in time order."""
    try:
        with open(path) as f:
            files = json.load(f)["files"]
    except (OSError, ValueError, KeyError) as e:
        fail(f"{path}: not a readable .vtp.series file ({e})")
    base = os.path.dirname(path)
    frames = sorted((os.path.join(base, entry["name"]), float(entry["time"])) for entry in files)
    frames.sort(key=lambda f: f[1])
    if not frames:
        fail(f"{path} lists no files")
    return frames


def pick_frame(frames, frame, path):
    """The frame of a series: index K (negative from the end) or 't=T' (nearest time)."""
    if frame is None:
        return frames[-1]
    if frame.startswith("t="):
        t = float(frame[2:])
        return min(frames, key=lambda f: abs(f[1] - t))
    try:
        return frames[int(frame)]
    except (ValueError, IndexError):
        fail(f"--frame {frame}: {path} has frames 0 to {len(frames) - 1} (or use t=TIME)")


def state_from(path, frame=None, wire=None, label=None):
    """A State from a grains .vtp, a grains .vtp.series or a directory (see the docstring)."""
    if os.path.isdir(path):
        where = path
        if not os.path.exists(os.path.join(where, "grains.vtp.series")) and \
                os.path.exists(os.path.join(where, "post", "grains.vtp.series")):
            where = os.path.join(where, "post")
        series = os.path.join(where, "grains.vtp.series")
        if not os.path.exists(series):
            fail(f"{path}: no grains.vtp.series here nor in {os.path.join(path, 'post')}")
        path = series
    if path.endswith(".vtp.series"):
        grains_file, t = pick_frame(read_series(path), frame, path)
        if wire is None:
            wire_series = os.path.join(os.path.dirname(path), os.path.basename(path).replace("grains", "wire"))
            if wire_series != path and os.path.exists(wire_series):
                wire = min(read_series(wire_series), key=lambda f: abs(f[1] - t))[0]
        return State(grains_file, wire, label if label is not None else f"t = {t:g}")
    if not path.endswith(".vtp"):
        fail(f"{path}: expected a grains .vtp file, a .vtp.series file or a directory")
    if not os.path.exists(path):
        fail(f"{path} does not exist")
    if frame is not None:
        fail(f"a frame ({frame}) is for a series or a directory, not for the file {path}")
    if wire is None:
        wire = wire_beside(path)
    return State(path, wire, label if label is not None else f"step {step_of(path)}")


# --- a display for VTK's X render window ----------------------------------------------

def start_xvfb(width, height):
    """Start Xvfb on a free display number (it picks one: -displayfd) and point DISPLAY at it.
    Returns the process, or None when a display is already set or the VTK build renders
    without X (EGL or OSMesa)."""
    import vtk
    if os.environ.get("DISPLAY") or "XOpenGL" not in type(vtk.vtkRenderWindow()).__name__:
        return None
    read_end, write_end = os.pipe()
    try:
        proc = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0",
                                 f"{max(width, 1280)}x{max(height, 1024)}x24", "-nolisten", "tcp"],
                                pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    except FileNotFoundError:
        fail("no display (DISPLAY is unset) and no Xvfb to render in: install Debian's xvfb "
             "(./build.sh deps), or run under xvfb-run")
    os.close(write_end)
    number = b""
    while not number.endswith(b"\n"):
        chunk = os.read(read_end, 64)
        if not chunk:
            break
        number += chunk
    os.close(read_end)
    if not number.strip():
        proc.kill()
        fail("Xvfb did not start")
    os.environ["DISPLAY"] = ":" + number.decode().strip()
    return proc


# --- the scene ----------------------------------------------------------------------------

def write_png(window, path):
    """Render `window` and write it to the PNG `path` (RGB, the back buffer); the window is
    finalised before a private Xvfb goes away. Returns whether the file was written."""
    import vtk
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    window.Finalize()
    return writer.GetErrorCode() == 0 and os.path.exists(path)


def colour_bar_renderer(lut, bar_width, label_font, title, title_font, title_y):
    """A renderer for the right `bar_width` of the window: the colour bar of `lut` with its
    labels at `label_font` points and `title` above it (at height `title_y` of the viewport)."""
    import vtk
    renderer = vtk.vtkRenderer()
    renderer.SetViewport(1.0 - bar_width, 0.0, 1.0, 1.0)
    renderer.SetBackground(1.0, 1.0, 1.0)
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("")
    bar.SetNumberOfLabels(5)
    bar.SetLabelFormat("%.2g")
    bar.UnconstrainedFontSizeOn()
    bar.SetBarRatio(0.3)
    for prop in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        prop.SetColor(0.1, 0.1, 0.1)
        prop.SetFontSize(label_font)
        prop.BoldOff()
        prop.ItalicOff()
        prop.ShadowOff()
    bar.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    bar.SetPosition(0.1, 0.1)
    bar.SetWidth(0.85)
    bar.SetHeight(0.7)
    renderer.AddActor2D(bar)
    renderer.AddActor2D(text_actor(title, title_font, 0.5, title_y))
    return renderer


def energy_lookup(vmin, vmax):
    import vtk
    ctf = vtk.vtkColorTransferFunction()
    for k, rgb in enumerate(PLASMA):
        ctf.AddRGBPoint(vmin + (vmax - vmin) * k / (len(PLASMA) - 1), *rgb)
    lut = vtk.vtkLookupTable()
    lut.SetNumberOfTableValues(256)
    lut.SetRange(vmin, vmax)
    for k in range(256):
        lut.SetTableValue(k, *ctf.GetColor(vmin + (vmax - vmin) * k / 255.0), 1.0)
    lut.Build()
    return lut


def grain_actor(data):
    """The grains' faces, each grain one shade of sand (its id spread by the golden ratio)."""
    import vtk
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    ids = data.GetCellData().GetArray("id")
    ids = vtk_to_numpy(ids) if ids is not None else np.zeros(data.GetNumberOfCells())
    shade = 0.78 + 0.22 * np.modf(ids * 0.6180339887)[0]
    rgb = np.clip(255.0 * shade[:, None] * GRAIN_RGB[None, :], 0, 255).astype(np.uint8)
    colours = numpy_to_vtk(rgb, deep=True)
    colours.SetName("grain_colour")
    data.GetCellData().SetScalars(colours)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(data)
    mapper.SetScalarModeToUseCellData()
    mapper.SetColorModeToDirectScalars()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetInterpolationToFlat()
    prop.SetAmbient(0.35)
    prop.SetDiffuse(0.8)
    prop.SetSpecular(0.1)
    return actor


def wire_actors(data, lut, tube_radius):
    """The wire as tubes along its polylines and a ball at every bead (smooth joints; lone
    beads show), coloured by the beads' elastic energy when the file has it."""
    import vtk
    has_energy = data.GetPointData().GetArray(ENERGY) is not None
    if has_energy:
        data.GetPointData().SetActiveScalars(ENERGY)
    clean = vtk.vtkCleanPolyData()   # consecutive coincident beads would break the tube
    clean.SetInputData(data)
    tube = vtk.vtkTubeFilter()
    tube.SetInputConnection(clean.GetOutputPort())
    tube.SetRadius(tube_radius)
    tube.SetNumberOfSides(12)
    tube.CappingOn()
    ball = vtk.vtkSphereSource()
    ball.SetRadius(tube_radius)
    ball.SetThetaResolution(12)
    ball.SetPhiResolution(8)
    balls = vtk.vtkGlyph3D()
    balls.SetInputData(data)
    balls.SetSourceConnection(ball.GetOutputPort())
    balls.ScalingOff()
    balls.OrientOff()
    balls.SetColorModeToColorByScalar()
    actors = []
    for source in (tube, balls):
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        if has_energy:
            mapper.SetScalarModeToUsePointFieldData()
            mapper.SelectColorArray(ENERGY)
            mapper.SetLookupTable(lut)
            mapper.UseLookupTableScalarRangeOn()
            mapper.InterpolateScalarsBeforeMappingOn()
        else:
            mapper.ScalarVisibilityOff()
            actor.GetProperty().SetColor(*WIRE_RGB)
        actor.GetProperty().SetSpecular(0.3)
        actor.GetProperty().SetSpecularPower(20)
        actors.append(actor)
    return actors, has_energy


def floor_actor(bounds, z):
    import vtk
    plane = vtk.vtkPlaneSource()
    plane.SetOrigin(bounds[0], bounds[2], z)
    plane.SetPoint1(bounds[1], bounds[2], z)
    plane.SetPoint2(bounds[0], bounds[3], z)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(plane.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.88, 0.89, 0.91)
    actor.GetProperty().SetAmbient(0.5)
    actor.GetProperty().SetDiffuse(0.5)
    return actor


def text_actor(text, size, x, y, justify="centre"):
    import vtk
    actor = vtk.vtkTextActor()
    actor.SetInput(text)
    prop = actor.GetTextProperty()
    prop.SetFontSize(size)
    prop.SetColor(0.1, 0.1, 0.1)
    prop.SetJustificationToCentered() if justify == "centre" else prop.SetJustificationToLeft()
    prop.SetVerticalJustificationToTop()
    actor.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    actor.SetPosition(x, y)
    return actor


def view_frame(bounds, elevation, azimuth):
    """The camera's direction (centre → camera), up and right vectors, the box's centre and
    its half extents across and up the picture, seen from elevation/azimuth."""
    el, az = np.radians(elevation), np.radians(azimuth)
    toward = np.array([np.sin(az) * np.cos(el), -np.cos(az) * np.cos(el), np.sin(el)])
    up = np.array([0.0, 0.0, 1.0]) if elevation < 89.0 else np.array([-np.sin(az), np.cos(az), 0.0])
    right = np.cross(up, toward)
    right /= np.linalg.norm(right)
    up = np.cross(toward, right)
    centre = np.array([(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2])
    corners = np.array([[x, y, z] for x in bounds[0:2] for y in bounds[2:4] for z in bounds[4:6]]) - centre
    return toward, up, centre, np.abs(corners @ right).max(), np.abs(corners @ up).max(), \
        np.linalg.norm(corners, axis=1).max()


def place_camera(renderer, frame, aspect, titled):
    """Parallel projection that fits the box of `frame` into a viewport of width/height
    `aspect` with a margin, below the title band (the top 10 %) when there is a title."""
    toward, up, centre, half_w, half_h, size = frame
    band = 0.9 if titled else 1.0
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + 4.0 * size * toward))
    camera.SetViewUp(*up)
    camera.SetParallelScale(1.06 * max(half_h / band, half_w / aspect))
    camera.SetWindowCenter(0.0, 1.0 - band)   # the picture's centre moves down by half the band
    renderer.ResetCameraClippingRange()


def read_wire(path):
    """A wire .vtp, or None when it holds no bead."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode() != 0:
        fail(f"{path}: not a readable VTK XML PolyData file")
    data = reader.GetOutput()
    return data if data.GetNumberOfPoints() > 0 else None


def union_bounds(datasets):
    b = np.array([d.GetBounds() for d in datasets if d is not None and d.GetNumberOfPoints() > 0])
    return [b[:, 0].min(), b[:, 1].max(), b[:, 2].min(), b[:, 3].max(), b[:, 4].min(), b[:, 5].max()]


def render(states, args):
    import vtk
    from vtkmodules.util.numpy_support import vtk_to_numpy
    width, height = args.size
    loaded = []
    for s in states:
        grains = read_polydata(s.grains) if s.grains else None
        # (a series may start before the wire is laid: its first files hold no bead)
        wire = read_wire(s.wire) if s.wire else None
        loaded.append((grains, wire))
    datasets = [d for pair in loaded for d in pair if d is not None]
    if not datasets:
        fail("nothing to draw")
    bounds = union_bounds(datasets)
    pad = args.tube_radius
    bounds = [bounds[0] - pad, bounds[1] + pad, bounds[2] - pad, bounds[3] + pad, bounds[4] - pad, bounds[5] + pad]
    floor = None if args.floor == "none" else float(args.floor)
    if floor is not None:
        # the floor reaches 5 % of the width beyond the column, and is in the picture
        pad = 0.05 * max(bounds[1] - bounds[0], bounds[3] - bounds[2])
        bounds = [bounds[0] - pad, bounds[1] + pad, bounds[2] - pad, bounds[3] + pad, min(bounds[4], floor), bounds[5]]

    energies = [vtk_to_numpy(w.GetPointData().GetArray(ENERGY)) for _, w in loaded
                if w is not None and w.GetPointData().GetArray(ENERGY) is not None]
    if args.energy_range:
        vmin, vmax = args.energy_range
    else:
        # 0 to the 99th percentile of the beads shown: the energy gathers in a few beads, and
        # a scale to the largest would leave the rest of the wire in the lowest colour
        beads = np.concatenate([e for e in energies if e.size]) if any(e.size for e in energies) else np.zeros(1)
        vmin, vmax = 0.0, float(np.percentile(beads, 99.0))
        if vmax <= vmin:
            vmax = max(float(beads.max()), vmin + 1.0)
    lut = energy_lookup(vmin, vmax)

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(width, height)
    window.SetMultiSamples(0)
    bar_width = 0.12 if energies else 0.0
    font = max(10, int(round(height / 32)))
    elevation = args.elevation if args.elevation is not None else VIEWS[args.view][0]
    azimuth = args.azimuth if args.azimuth is not None else VIEWS[args.view][1]
    frame = view_frame(bounds, elevation, azimuth)
    titles = [state.label if len(states) > 1 or args.title is None else args.title for state in states]
    # the panels in a row (side by side) or a column (stacked): the one that draws them larger
    n = len(states)
    layout = args.layout
    if layout == "auto":
        def scale(w, h):   # pixels per length of a panel w x h (fractions of the picture)
            return min(w * width / frame[3], h * height * (0.9 if any(titles) else 1.0) / frame[4])
        layout = "row" if scale((1.0 - bar_width) / n, 1.0) >= scale(1.0 - bar_width, 1.0 / n) else "column"
    for k, ((grains, wire), title) in enumerate(zip(loaded, titles)):
        renderer = vtk.vtkRenderer()
        if layout == "row":
            w, h = (1.0 - bar_width) / n, 1.0
            renderer.SetViewport(k * w, 0.0, (k + 1) * w, 1.0)
        else:
            w, h = 1.0 - bar_width, 1.0 / n
            renderer.SetViewport(0.0, 1.0 - (k + 1) * h, w, 1.0 - k * h)
        renderer.SetBackground(1.0, 1.0, 1.0)
        renderer.UseFXAAOn()
        lights = vtk.vtkLightKit()   # key, fill and back lights that follow the camera
        lights.AddLightsToRenderer(renderer)
        if grains is not None:
            renderer.AddActor(grain_actor(grains))
        if wire is not None:
            for actor in wire_actors(wire, lut, args.tube_radius)[0]:
                renderer.AddActor(actor)
        if floor is not None:
            renderer.AddActor(floor_actor(bounds, floor))
        if title:
            renderer.AddActor2D(text_actor(title, font, 0.5, 0.97))
        place_camera(renderer, frame, w * width / (h * height), bool(title))
        window.AddRenderer(renderer)
    if energies:
        window.AddRenderer(colour_bar_renderer(lut, bar_width, int(font * 0.65), "wire elastic\nenergy\nper bead",
                                               int(font * 0.7), 0.95))

    if not write_png(window, args.out):
        fail(f"cannot write {args.out}")
    shown = ", ".join(os.path.basename(s.grains or s.wire) for s in states)
    scale = f"; wire energy {vmin:.3g} to {vmax:.3g}" if energies else ""
    print(f"render_column.py: wrote {args.out} ({width}x{height}; {shown}{scale})")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--grains", help="grains .vtp file (dump polyhedron/vtk)")
    parser.add_argument("--wire", help="wire .vtp file (dump wire/vtk); default: the file beside --grains")
    parser.add_argument("--no-wire", action="store_true", help="draw no wire")
    parser.add_argument("--series", metavar="STATE", help="a directory or .vtp.series file (see above)")
    parser.add_argument("--frame", help="with --series: index K into the series or t=TIME")
    parser.add_argument("--before", nargs="+", metavar=("STATE", "FRAME"), help="the left panel")
    parser.add_argument("--after", nargs="+", metavar=("STATE", "FRAME"), help="the right panel")
    parser.add_argument("--titles", nargs=2, metavar=("LEFT", "RIGHT"), help="panel titles of --before/--after")
    parser.add_argument("--title", help='title of a single picture (default: its time or step; "" for none)')
    parser.add_argument("--out", "-o", required=True, help="the PNG to write")
    parser.add_argument("--size", nargs=2, type=int, default=[1200, 900], metavar=("W", "H"))
    parser.add_argument("--view", choices=sorted(VIEWS), default="elevated")
    parser.add_argument("--elevation", type=float, help="degrees above the horizontal")
    parser.add_argument("--azimuth", type=float, help="degrees about z, 0 looking along +y")
    parser.add_argument("--energy-range", nargs=2, type=float, metavar=("MIN", "MAX"))
    parser.add_argument("--tube-radius", type=float, default=0.1, help="the wire's drawn radius (default 0.1)")
    parser.add_argument("--floor", default="0", help="height of the floor drawn, or none (default 0)")
    parser.add_argument("--layout", choices=("auto", "row", "column"), default="auto",
                        help="two panels side by side (row) or stacked (column); auto: the larger picture")
    args = parser.parse_args()
    if args.size[0] < 16 or args.size[1] < 16:
        parser.error("--size: at least 16 x 16 pixels")
    if args.tube_radius <= 0:
        parser.error("--tube-radius must be > 0")
    if args.energy_range and args.energy_range[1] <= args.energy_range[0]:
        parser.error("--energy-range: MAX must be > MIN")
    pair = args.before is not None or args.after is not None
    if pair:
        if args.before is None or args.after is None:
            parser.error("--before and --after go together")
        if args.grains or args.series or args.frame:
            parser.error("--before/--after take the place of --grains and --series")
        for name, value in (("--before", args.before), ("--after", args.after)):
            if len(value) > 2:
                parser.error(f"{name}: STATE [FRAME]")
        titles = args.titles or [None, None]
        states = [state_from(value[0], value[1] if len(value) > 1 else None, label=title)
                  for value, title in zip((args.before, args.after), titles)]
    elif args.series:
        if args.grains:
            parser.error("--series or --grains, not both")
        states = [state_from(args.series, args.frame, wire=args.wire)]
    elif args.grains:
        if args.frame:
            parser.error("--frame is for --series")
        states = [state_from(args.grains, wire=args.wire)]
    elif args.wire:
        states = [State(None, args.wire, "")]
    else:
        parser.error("nothing to draw: --grains, --series or --before/--after")
    if args.no_wire:
        for s in states:
            s.wire = None
    for s in states:
        for path in (s.grains, s.wire):
            if path and not os.path.exists(path):
                fail(f"{path} does not exist")

    xvfb = start_xvfb(*args.size)
    try:
        render(states, args)
    finally:
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()


if __name__ == "__main__":
    main()
