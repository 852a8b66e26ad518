#!/usr/bin/env bash
# Layering (issue 43): every module includes only the headers of the modules it links, as
# src/CMakeLists.txt declares them (tools/check_layering.py). The real tree must pass; a copy
# with a forbidden include (sph including run), one with a folder no module declares, one
# including a header that does not exist and one hiding an include between comment
# look-alikes must each fail, naming the file and the module.
# Usage: tests/layering_test.sh <repo-root>
set -euo pipefail
if [ $# -ne 1 ]; then
  echo "usage: $0 <repo-root>" >&2
  exit 2
fi
root="$(cd "$1" && pwd)"
python=/usr/bin/python3
checker="$root/tools/check_layering.py"

tmp="$(mktemp -d)"
cleanup() { rm -rf "$tmp"; }
trap cleanup EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }

# A fresh copy of src/ and the checker, as a repository of its own.
copy() {
  local dir="$tmp/$1"
  mkdir -p "$dir/tools"
  cp -R "$root/src" "$dir/src"
  cp "$checker" "$dir/tools/check_layering.py"
  echo "$dir"
}

# Runs the checker on a copy that must fail; prints its output.
expect_failure() {
  local dir="$1" rc=0 out
  out="$("$python" "$dir/tools/check_layering.py" --root "$dir" 2>&1)" || rc=$?
  [ "$rc" -eq 1 ] || { echo "$out" >&2; fail "checker exited $rc on $dir, expected 1"; }
  echo "$out"
}

# 1. The real tree passes.
echo "== real tree"
"$python" "$checker" --root "$root" || fail "the real tree breaks the layering (see above)"

# 2. A low module (sph: it links core only) including a high one (run).
echo "== forbidden include"
dir="$(copy forbidden)"
victim="$(cd "$dir" && find src/netsph/sph -maxdepth 1 -name '*.hpp' | sort | head -n 1)"
[ -n "$victim" ] || fail "no header in src/netsph/sph to inject into"
[ -f "$dir/src/netsph/run/runner.hpp" ] || fail "src/netsph/run/runner.hpp is gone: pick another high header"
[ -z "$(tail -c 1 "$dir/$victim")" ] || echo >> "$dir/$victim"
line=$(( $(wc -l < "$dir/$victim") + 1 ))
echo '#include "netsph/run/runner.hpp"' >> "$dir/$victim"
out="$(expect_failure "$dir")"
expected="$victim:$line: includes netsph/run/runner.hpp (module run), but netsph_sph does not link netsph_run"
grep -qxF "$expected" <<< "$out" || { echo "$out" >&2; fail "expected the line: $expected"; }

# 3. A folder that no module declares.
echo "== undeclared folder"
dir="$(copy undeclared)"
mkdir -p "$dir/src/netsph/undeclared"
printf '#pragma once\n#include "netsph/core/error.hpp"\n' > "$dir/src/netsph/undeclared/x.hpp"
out="$(expect_failure "$dir")"
grep -q '^src/netsph/undeclared/: .*no module' <<< "$out" || { echo "$out" >&2; fail "undeclared folder not named"; }

# 4. An include of a netsph header that does not exist.
echo "== missing header"
dir="$(copy missing)"
victim="$(cd "$dir" && find src/netsph/core -maxdepth 1 -name '*.hpp' | sort | head -n 1)"
[ -z "$(tail -c 1 "$dir/$victim")" ] || echo >> "$dir/$victim"
line=$(( $(wc -l < "$dir/$victim") + 1 ))
echo '#include "netsph/core/no_such_header.hpp"' >> "$dir/$victim"
out="$(expect_failure "$dir")"
grep -qxF "$victim:$line: includes netsph/core/no_such_header.hpp, which does not exist" <<< "$out" \
  || { echo "$out" >&2; fail "missing header not named"; }

# 5. A forbidden include after a "/*" in a line comment and before a "*/" in a later
# comment: the text between is not a block comment, and the include is still seen.
echo "== include between comment look-alikes"
dir="$(copy lookalike)"
victim="$(cd "$dir" && find src/netsph/sph -maxdepth 1 -name '*.hpp' | sort | head -n 1)"
[ -z "$(tail -c 1 "$dir/$victim")" ] || echo >> "$dir/$victim"
line=$(( $(wc -l < "$dir/$victim") + 2 ))
printf '// files such as snapshots/*.h5\n#include "netsph/run/runner.hpp"\nint f(int /*unused*/);\n' \
  >> "$dir/$victim"
out="$(expect_failure "$dir")"
expected="$victim:$line: includes netsph/run/runner.hpp (module run), but netsph_sph does not link netsph_run"
grep -qxF "$expected" <<< "$out" || { echo "$out" >&2; fail "expected the line: $expected"; }

echo "PASS: layering checker"
