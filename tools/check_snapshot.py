#!/usr/bin/python3
"""Checks a netsph output folder's snapshots the way a reader will see them.

Usage: check_snapshot.py OUTDIR [BASE]

Parses OUTDIR/BASE.xdmf (BASE defaults to "particles") and checks, for every grid of the
temporal collection, that each referenced HDF5 dataset exists with the declared dimensions
and number type, that the Polyvertex connectivity is 0..N-1 and that the times increase.
Prints "ok: <n> snapshots, <N> particles in the last, times [t0 .. tN]" and exits 0, or
prints every problem found and exits 1.

Run it with Debian's /usr/bin/python3, which has h5py (python3-h5py).
"""
import os
import sys
import xml.etree.ElementTree as ET

try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"error: {e} (run with /usr/bin/python3; apt-get install python3-h5py)")
    sys.exit(1)

# (NumberType, Precision) -> numpy dtype, as XDMF 3 defines them.
DTYPES = {
    ("Float", "8"): np.dtype("<f8"),
    ("Float", "4"): np.dtype("<f4"),
    ("Int", "8"): np.dtype("<i8"),
    ("Int", "4"): np.dtype("<i4"),
    ("UInt", "4"): np.dtype("<u4"),
    ("UChar", "1"): np.dtype("u1"),
    ("Char", "1"): np.dtype("i1"),
}


class Checker:
    def __init__(self, xdmf_path):
        self.xdmf_path = xdmf_path
        self.folder = os.path.dirname(os.path.abspath(xdmf_path))
        self.problems = []
        self.files = {}  # relative path -> open h5py.File, or None when it cannot be opened

    def problem(self, where, text):
        self.problems.append(f"{where}: {text}")

    def h5file(self, relative):
        if relative not in self.files:
            path = os.path.join(self.folder, relative)
            try:
                self.files[relative] = h5py.File(path, "r")
            except OSError as e:
                self.problems.append(f"{path}: cannot open: {e}")
                self.files[relative] = None
        return self.files[relative]

    def close(self):
        for f in self.files.values():
            if f is not None:
                f.close()

    def data_item(self, where, item, expected_rows=None, expected_cols=None):
        """Checks one <DataItem>; returns its dataset (as a numpy array) or None."""
        if item is None:
            self.problem(where, "missing DataItem")
            return None
        if item.get("Format") != "HDF":
            self.problem(where, f"Format is {item.get('Format')!r}, expected 'HDF'")
            return None
        try:
            dims = tuple(int(d) for d in item.get("Dimensions", "").split())
        except ValueError:
            self.problem(where, f"bad Dimensions {item.get('Dimensions')!r}")
            return None
        ref = (item.text or "").strip()
        if ":" not in ref:
            self.problem(where, f"bad HDF reference {ref!r} (expected file.h5:/dataset)")
            return None
        relative, dataset = ref.rsplit(":", 1)
        where = f"{where} ({ref})"
        f = self.h5file(relative)
        if f is None:
            return None
        if dataset not in f:
            self.problem(where, "dataset not found")
            return None
        d = f[dataset]
        if d.shape != dims:
            self.problem(where, f"shape {d.shape} but Dimensions {dims}")
        key = (item.get("NumberType", "Float"), item.get("Precision", "4"))
        if key not in DTYPES:
            self.problem(where, f"unknown NumberType/Precision {key}")
        elif d.dtype != DTYPES[key]:
            self.problem(where, f"dtype {d.dtype} but declared {key[0]} {key[1]}")
        if expected_rows is not None and (len(dims) == 0 or dims[0] != expected_rows):
            self.problem(where, f"Dimensions {dims} do not match {expected_rows} points")
        if expected_cols is not None and (len(dims) != 2 or dims[1] != expected_cols):
            self.problem(where, f"Dimensions {dims}, expected N x {expected_cols}")
        return d[()]

    def grid(self, grid):
        """Checks one uniform grid; returns (time, particle count)."""
        where = f"{self.xdmf_path}: grid {grid.get('Name')!r}"
        time_el = grid.find("Time")
        time = None
        try:
            time = float(time_el.get("Value"))
        except (AttributeError, TypeError, ValueError):
            self.problem(where, "missing or bad <Time Value=...>")

        n = None
        topo = grid.find("Topology")
        if topo is None or topo.get("TopologyType") != "Polyvertex":
            self.problem(where, "missing Polyvertex Topology")
        else:
            try:
                n = int(topo.get("NumberOfElements"))
            except (TypeError, ValueError):
                self.problem(where, "bad Topology NumberOfElements")
            # ParaView 5.11's Xdmf3 readers build no cells without explicit connectivity.
            conn = self.data_item(f"{where} Topology", topo.find("DataItem"), n)
            if conn is not None and n is not None and conn.shape == (n,):
                if not np.array_equal(conn, np.arange(n)):
                    self.problem(f"{where} Topology", "connectivity is not 0..N-1")

        geom = grid.find("Geometry")
        if geom is None or geom.get("GeometryType") != "XYZ":
            self.problem(where, "missing XYZ Geometry")
        else:
            self.data_item(f"{where} Geometry", geom.find("DataItem"), n, 3)

        for attr in grid.findall("Attribute"):
            name = attr.get("Name")
            kind = attr.get("AttributeType", "Scalar")
            cols = 3 if kind == "Vector" else None
            item_where = f"{where} Attribute {name!r}"
            if attr.get("Center") != "Node":
                self.problem(item_where, f"Center is {attr.get('Center')!r}, expected 'Node'")
            values = self.data_item(item_where, attr.find("DataItem"), n, cols)
            if kind == "Scalar" and values is not None and values.ndim != 1:
                self.problem(item_where, f"a Scalar with shape {values.shape}")
        return time, n

    def run(self):
        try:
            root = ET.parse(self.xdmf_path).getroot()
        except (OSError, ET.ParseError) as e:
            self.problems.append(f"{self.xdmf_path}: cannot parse: {e}")
            return None
        collection = root.find("Domain/Grid")
        if (collection is None or collection.get("GridType") != "Collection"
                or collection.get("CollectionType") != "Temporal"):
            self.problem(self.xdmf_path, "no temporal collection Grid under Domain")
            return None
        grids = collection.findall("Grid")
        if not grids:
            self.problem(self.xdmf_path, "the collection lists no snapshots")
            return None
        names = [g.get("Name") for g in grids]
        if len(set(names)) != len(names):
            self.problem(self.xdmf_path, "grid names are not unique")
        results = [self.grid(g) for g in grids]
        times = [t for t, _ in results]
        for i in range(1, len(times)):
            if times[i] is not None and times[i - 1] is not None and times[i] < times[i - 1]:
                self.problem(self.xdmf_path, f"time goes back at grid {names[i]!r}")
        return results


def main(argv):
    if len(argv) not in (2, 3) or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 1
    base = argv[2] if len(argv) == 3 else "particles"
    xdmf = os.path.join(argv[1], base + ".xdmf")
    checker = Checker(xdmf)
    try:
        results = checker.run()
    finally:
        checker.close()
    if checker.problems:
        for p in checker.problems:
            print(p)
        return 1
    times = [t for t, _ in results]
    print(f"ok: {len(results)} snapshots, {results[-1][1]} particles in the last, "
          f"times [{times[0]:.9g} .. {times[-1]:.9g}]")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
