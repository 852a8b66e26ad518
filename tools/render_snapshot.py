"""Render the latest snapshot of a netsph run folder to PNG with ParaView (pvpython/pvbatch).

    xvfb-run -a pvbatch tools/render_snapshot.py RUN_DIR [--out FILE.png] [--report FILE.json]

Loads RUN_DIR/particles.xdmf (the fluid and boundary particles; by absolute path, which
ParaView 5.11's XDMF 3 reader needs) at its last time, draws the fluid particles coloured by
speed and the walls and bodies in grey, adds every net's <net>.xdmf (knots as points, twines
as lines coloured by tension), and writes the picture (default RUN_DIR/plots/snapshot.png).
--report writes what ParaView read: the point count and the speed and pressure ranges of the
last snapshot, and each net's knots, twines and tension range, for tests/paraview_test.sh. Debian's ParaView renders through GLX
only, so it needs an X server: xvfb-run provides one on a machine without a display.
"""
import argparse
import glob
import json
import os

from paraview import simple as pv


def label_bar(lut, view, title):
    """Dark text on the white background, and the unit in the title."""
    bar = pv.GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir")
    parser.add_argument("--out", help="PNG file (default RUN_DIR/plots/snapshot.png)")
    parser.add_argument("--report", help="JSON file: points and field ranges read")
    args = parser.parse_args()
    run_dir = os.path.abspath(args.run_dir)
    xdmf = os.path.join(run_dir, "particles.xdmf")
    if not os.path.exists(xdmf):
        raise SystemExit(f"render_snapshot: {xdmf} not found (a run without snapshots?)")
    out = args.out or os.path.join(run_dir, "plots", "snapshot.png")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)

    particles = pv.Xdmf3ReaderT(FileName=[xdmf])
    try:
        times = [float(t) for t in particles.TimestepValues]
    except TypeError:  # a single snapshot gives a bare number
        times = [float(particles.TimestepValues)]
    last = times[-1] if times else 0.0
    view = pv.GetActiveViewOrCreate("RenderView")
    view.ViewTime = last
    view.ViewSize = [1280, 800]
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    particles.UpdatePipeline(last)

    speed = pv.Calculator(Input=particles, ResultArrayName="speed", Function="mag(velocity)")
    fluid = pv.Threshold(Input=speed, Scalars=["POINTS", "kind"])
    solid = pv.Threshold(Input=speed, Scalars=["POINTS", "kind"])
    # kind: 0 fluid, 1 wall, 2 buffer, 3 body (sph/particle_set.hpp)
    for f, lo, hi in ((fluid, 0, 0), (solid, 1, 1)):
        if hasattr(f, "LowerThreshold"):
            f.LowerThreshold, f.UpperThreshold = lo, hi
        else:  # ParaView before 5.10
            f.ThresholdRange = [lo, hi]
    fluid_display = pv.Show(fluid, view)
    pv.ColorBy(fluid_display, ("POINTS", "speed"))
    lut = pv.GetColorTransferFunction("speed")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    fluid_display.SetScalarBarVisibility(view, True)
    label_bar(lut, view, "fluid speed [m/s]")
    fluid_display.PointSize = 3
    solid_display = pv.Show(solid, view)
    pv.ColorBy(solid_display, None)
    solid_display.AmbientColor = solid_display.DiffuseColor = [0.6, 0.6, 0.6]
    solid_display.Opacity = 0.3

    nets = {}
    for xdmf_net in sorted(glob.glob(os.path.join(run_dir, "*.xdmf"))):
        if os.path.basename(xdmf_net) == "particles.xdmf":
            continue
        net = pv.Xdmf3ReaderT(FileName=[xdmf_net])
        net.UpdatePipeline(last)
        info = net.GetDataInformation()
        nets[os.path.basename(xdmf_net)[:-5]] = {
            "points": info.GetNumberOfPoints(),
            "cells": info.GetNumberOfCells(),
            "tension_range": list(net.CellData["tension"].GetRange()),
        }
        shown = pv.Show(net, view)
        pv.ColorBy(shown, ("CELLS", "tension"))
        tension = pv.GetColorTransferFunction("tension")
        tension.ApplyPreset("Inferno (matplotlib)", True)
        shown.LineWidth = 3
        shown.SetScalarBarVisibility(view, True)
        label_bar(tension, view, "twine tension [N]")

    view.CameraPosition = [0, -1, 0.3]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    pv.Render(view)
    pv.SaveScreenshot(out, view, ImageResolution=[1280, 800])

    if args.report:
        speed.UpdatePipeline(last)
        data = pv.servermanager.Fetch(speed)
        info = speed.GetDataInformation()
        report = {
            "time": last,
            "points": info.GetNumberOfPoints(),
            "speed_range": list(speed.PointData["speed"].GetRange()),
            "pressure_range": list(speed.PointData["pressure"].GetRange()),
            "image": os.path.abspath(out),
            "nets": nets,
        }
        del data
        with open(args.report, "w") as f:
            json.dump(report, f, indent=1)
    print(os.path.abspath(out))


if __name__ == "__main__":
    main()
