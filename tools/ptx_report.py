#!/usr/bin/python3
"""What nvcc makes of the device rates kernel, without a GPU: registers and spills (ptxas -v)
and the PTX count of IEEE divisions, reciprocals and square roots, for each variant of the
rates pass of one model (kernel, viscosity, diffusion; with and without shifting) at each
register cap (none, 80, 64: RatesRegisterCap).

A static check for sessions without a device: it says whether a change to the pair terms
added divisions or spills, not how fast the kernel runs (that needs `netsph bench --backend
cuda`, docs/PERFORMANCE.md "CUDA").

    /usr/bin/python3 tools/ptx_report.py [--build-dir build] [--model WendlandC2,0,2]

--model: kernel type, ViscosityModel (0 artificial, 1 laminar) and DensityDiffusion (0 none,
1 Molteni, 2 Fourtakas) as they appear in the kernel's template arguments; the default is
the benchmark's model. Compiles backend/cuda/device_run_cuda.cu once (about three minutes on
two idle cores) in a temporary folder, with the compiler and flags CMake chose for the build
folder (configured with CUDA), plus ptxas -v.
"""
import argparse
import os
import re
import shlex
import subprocess
import sys
import tempfile

CUDA_TARGET = "src/CMakeFiles/netsph_backend_cuda.dir"


def demangle(names):
    out = subprocess.run(["c++filt"], input="\n".join(names), capture_output=True, text=True)
    return dict(zip(names, out.stdout.split("\n")))


def build_flags(build):
    """The CUDA target's compiler and flags, as CMake wrote them into flags.make."""
    path = os.path.join(build, CUDA_TARGET, "flags.make")
    try:
        text = open(path).read()
    except OSError:
        sys.exit(f"{path}: not found; configure {build} with CUDA first (cmake -S . -B {build})")
    nvcc = re.search(r"# compile CUDA with (\S+)", text).group(1)
    flags = []
    for key in ("CUDA_DEFINES", "CUDA_INCLUDES", "CUDA_FLAGS"):
        m = re.search(rf"^{key} = (.*)$", text, re.M)
        flags += shlex.split(m.group(1)) if m else []
    # The include list is an options file named relative to the target's folder's parent.
    return nvcc, [os.path.join(build, "src", f) if f.endswith(".rsp") else f for f in flags]


def compile_tu(build, work):
    nvcc, flags = build_flags(build)
    src = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    cmd = [nvcc, *flags, "-Xptxas", "-v", "--keep", f"--keep-dir={work}", "-c",
           f"{src}/src/netsph/backend/cuda/device_run_cuda.cu", "-o", f"{work}/x.o"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"nvcc failed:\n{run.stderr[-4000:]}")
    return run.stderr


def resources(log):
    """Entry name -> (registers, spill stores, spill loads), in ptxas's order."""
    cur, spill, out = None, (0, 0), {}
    for line in log.split("\n"):
        m = re.search(r"Compiling entry function '(\S+)'", line)
        if m:
            cur, spill = m.group(1), (0, 0)
            continue
        m = re.search(r"(\d+) bytes spill stores, (\d+) bytes spill loads", line)
        if m and cur:
            spill = (int(m.group(1)), int(m.group(2)))
        m = re.search(r"Used (\d+) registers", line)
        if m and cur:
            out[cur] = (int(m.group(1)),) + spill
    return out


def ptx_counts(ptx):
    """Entry name -> counts of div.rn.f32, rcp.rn.f32 and sqrt.rn.f32."""
    out = {}
    for part in re.split(r"\n(?=(?:\.visible |\.weak )?\.entry )", ptx):
        m = re.match(r"(?:\.visible |\.weak )?\.entry (\S+)\(", part)
        if m:
            out[m.group(1)] = tuple(len(re.findall(rf"\b{op}\.rn\.f32\b", part))
                                    for op in ("div", "rcp", "sqrt"))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build-dir", default="build")
    ap.add_argument("--model", default="WendlandC2,0,2")
    args = ap.parse_args()
    kernel, visc, diff = args.model.split(",")
    with tempfile.TemporaryDirectory() as work:
        log = compile_tu(args.build_dir, work)
        with open(os.path.join(work, "device_run_cuda.ptx")) as f:
            ptx = f.read()
    res, counts = resources(log), ptx_counts(ptx)
    names = demangle(list(res))
    want = (f"netsph::{kernel}, (netsph::ViscosityModel){visc}, "
            f"(netsph::DensityDiffusion){diff}")
    print(f"rates kernel, {want.replace('netsph::', '')}")
    print("shift  cap    registers  spill stores/loads [B]  div.rn  rcp.rn  sqrt.rn")
    found = False
    for entry, (regs, st, ld) in res.items():
        m = re.search(r"rates_launch<([^>]*)>", names[entry])
        if not m or not m.group(1).startswith(want):
            continue
        shift = m.group(1).rsplit(", ", 1)[1]
        found = True
        # RatesRegisterCap: for_each_bounded_kernel<blocks a multiprocessor> caps the registers
        # (4 blocks: 64, 3 blocks: 80); for_each_kernel does not.
        bounded = re.match(r"void netsph::for_each_bounded_kernel<(\d+)u", names[entry])
        cap = {"4": "64", "3": "80"}.get(bounded.group(1), "?") if bounded else "none"
        div, rcp, sqrt = counts.get(entry, (0, 0, 0))
        print(f"{shift:6} {cap:6} {regs:9d}  {st:6d} / {ld:<14d}  {div:6d}  {rcp:6d}  {sqrt:7d}")
    if not found:
        sys.exit(f"no rates kernel for {want}: check --model")


if __name__ == "__main__":
    main()
