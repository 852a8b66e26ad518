#!/usr/bin/env bash
# `mpirun -n 2 netsph run` against one process. The floating box (walls, a floating body, a
# free surface): same steps and time, every particle present once, positions within 1e-3 dp,
# kinetic energy and the box's mean force within 1e-4 (the processes sum pairs and the box's
# loads in another order: round-off, amplified by the flow). A coupled net with inlet, outlet
# and probes (tests/cases/good/plot_smoke.toml): the same inflow and outflow counts, net
# deflection and tension, body forces and probe profile within 1e-4. Checkpoints of a
# distributed run continue as one process and as two. Skipped (77) without mpirun or when
# netsph was built without MPI.
set -euo pipefail
netsph="$1"
command -v mpirun >/dev/null || { echo "skip: no mpirun"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
args=(builtin:floating_box2d --set simulation.end_time=0.3 --set output.snapshot_every=0.1
      --threads 1 --no-plots)
"$netsph" -q run "${args[@]}" -o "$tmp/one"
mpirun -n 2 "$netsph" -q run "${args[@]}" -o "$tmp/two" 2>"$tmp/two.err" || {
  cat "$tmp/two.err"; exit 1; }
grep -q "MPI processes" "$tmp/two/log.txt" || { echo "skip: netsph built without MPI"; exit 77; }
/usr/bin/python3 - "$tmp/one" "$tmp/two" <<'PY'
import json, sys, os
import h5py, numpy as np
one, two = sys.argv[1], sys.argv[2]
a, b = (json.load(open(os.path.join(d, "summary.json"))) for d in (one, two))
assert b["performance"]["processes"] == 2, b["performance"]
assert a["time"]["steps"] == b["time"]["steps"], (a["time"], b["time"])
assert abs(a["time"]["simulated_s"] / b["time"]["simulated_s"] - 1) < 1e-9
assert a["particles"] == b["particles"], (a["particles"], b["particles"])
ke = abs(a["final_state"]["kinetic_energy_J"] / b["final_state"]["kinetic_energy_J"] - 1)
assert ke < 1e-4, ke
fa, fb = (np.array(s["bodies"][0]["force_N"]) for s in (a, b))
df = np.linalg.norm(fa - fb) / np.linalg.norm(fa)
assert df < 1e-4, (fa, fb)
snaps = sorted(os.listdir(os.path.join(one, "snapshots")))
assert snaps == sorted(os.listdir(os.path.join(two, "snapshots"))), "snapshot lists differ"
def state(d):
    with h5py.File(os.path.join(d, "snapshots", snaps[-1]), "r") as f:
        order = np.argsort(f["id"][:])
        return f["id"][:][order], f["position"][:][order]
ia, pa = state(one)
ib, pb = state(two)
assert np.array_equal(ia, ib), "particle ids differ: lost or doubled between processes"
dp = a["model"]["dp_m"]
dpos = np.abs(pa - pb).max() / dp
assert dpos < 1e-3, dpos
print(f"ok: 2 processes against 1: kinetic energy {ke:.2g}, box force {df:.2g}, "
      f"positions {dpos:.2g} dp")
PY
# The distributed run's checkpoint holds the whole state: one process continues it.
"$netsph" -q run --restart "$tmp/two" --set simulation.end_time=0.35 --threads 1 --no-plots
grep -q '"restarted_from_s"' "$tmp/two/summary.json"

# A net with inlet, outlet and probes, and a restart on two processes.
smoke=(--threads 1 --no-plots)
"$netsph" -q run "$2" "${smoke[@]}" -o "$tmp/net1"
mpirun -n 2 "$netsph" -q run "$2" "${smoke[@]}" -o "$tmp/net2" 2>"$tmp/net2.err" || {
  cat "$tmp/net2.err"; exit 1; }
/usr/bin/python3 - "$tmp/net1" "$tmp/net2" <<'PY'
import json, sys, os
a, b = (json.load(open(os.path.join(d, "summary.json"))) for d in sys.argv[1:3])
assert a["time"]["steps"] == b["time"]["steps"], (a["time"], b["time"])
assert a["particles"] == b["particles"], (a["particles"], b["particles"])
assert a["particles"]["inflow"] > 0 and a["particles"]["outflow"] > 0, a["particles"]
def close(x, y, what, rel=1e-4):
    # A vector (a force, a profile) within rel of its largest component: a component that is
    # zero but for round-off (a force across a symmetric flow) has no relative precision.
    if not isinstance(x, list): x, y = [x], [y]
    assert len(x) == len(y), (what, x, y)
    pairs = [(u, v) for u, v in zip(x, y) if u is not None or v is not None]  # None: no value
    assert all(u is not None and v is not None for u, v in pairs), (what, x, y)
    scale = max((max(abs(u), abs(v)) for u, v in pairs), default=0)
    for u, v in pairs:
        assert abs(u - v) <= rel * scale + 1e-9, (what, x, y)
for na, nb in zip(a["nets"], b["nets"]):
    for k in ("mean_max_deflection_m", "mean_max_tension_N", "final_bottom_displacement_m"):
        close(na[k], nb[k], k)
for ba, bb in zip(a["bodies"], b["bodies"]):
    close(ba["force_N"], bb["force_N"], "force_N")
close(a["probes"][0]["profile_mean_ux_m_s"], b["probes"][0]["profile_mean_ux_m_s"], "probe")
print("ok: net with inlet, outlet and probes on 2 processes as on 1")
PY
mpirun -n 2 "$netsph" -q run --restart "$tmp/net2" --set simulation.end_time=0.08 \
  "${smoke[@]}" 2>"$tmp/net2r.err" || { cat "$tmp/net2r.err"; exit 1; }
grep -q '"restarted_from_s"' "$tmp/net2/summary.json"
echo "ok: distributed runs, restarts on one and two processes"
