#!/usr/bin/python3
"""Check that every netsph module includes only the headers of modules it links.

Every module has src/ as a public include folder, so the compiler lets module A include a
header of module B even when A does not link B. This script closes that gap: it reads the
build's own link table from src/CMakeLists.txt and checks every include under src/netsph/.

The table (one source of truth, read from src/CMakeLists.txt):
  * netsph_module(<target> <folder> [DEPS ...] [PRIVATE_DEPS ...]) calls;
  * add_library(<netsph target> ...) / add_executable(netsph ...) whose sources are a
    file(GLOB var .../netsph/<folder>/*.ext) variable (the CUDA backend, the app), with
    their deps from target_link_libraries(<target> PUBLIC|INTERFACE|PRIVATE ...);
  * later target_link_libraries(<module target> ...) calls add to a module's deps too.
  Variables set by set(...) / list(APPEND|PREPEND|REMOVE_ITEM ...) are expanded. if()
  conditions are not evaluated: every branch counts, so the check covers the configuration
  with every optional part (CUDA, MPI) on. Non-netsph items (fmt::fmt, OpenMP::..., unset
  variables, generator expressions) are ignored. As netsph_module does, a module without
  .cpp files (an INTERFACE library) drops its PRIVATE_DEPS.

Module M may include: its own headers; for each direct dependency D (DEPS or PRIVATE_DEPS),
D's headers and those of every module D reaches through DEPS (public), transitively.

Usage: /usr/bin/python3 tools/check_layering.py [--root DIR]
Exit 0 with a one-line summary when clean, 1 with one line per problem otherwise.
"""

from __future__ import annotations

import argparse
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

SOURCE_SUFFIXES = {".hpp", ".cpp", ".cu", ".cuh"}
INCLUDE_RE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*([<"])([^">]+)[">]', re.MULTILINE)
GLOB_FOLDER_RE = re.compile(r"(?:^|/)netsph/(.+)/\*\.[A-Za-z0-9]+$")
VAR_RE = re.compile(r"\$\{([A-Za-z0-9_.+-]+)\}")


class TableError(Exception):
    """src/CMakeLists.txt could not be read as a module table."""


# ---------------------------------------------------------------------------------------
# CMake reading: a small lexer for commands and their arguments.

@dataclass
class Arg:
    text: str
    quoted: bool


@dataclass
class Command:
    name: str
    args: list[Arg]
    line: int


def lex_cmake(text: str, path: str) -> list[Command]:
    """Split CMake source into commands. Handles # and #[[ ]] comments, "quoted" and
    [[bracket]] arguments, nested parentheses, escapes. Comments inside quotes are text."""
    commands: list[Command] = []
    i, n, line = 0, len(text), 1

    def bracket_end(pos: int) -> tuple[int, int] | None:
        # text[pos] == '['; returns (content_start, close_len) for [==[ ... ]==]
        m = re.match(r"\[(=*)\[", text[pos:])
        if not m:
            return None
        return pos + m.end(), len(m.group(1))

    def skip_bracket(pos: int) -> tuple[int, str]:
        nonlocal line
        start, eqs = bracket_end(pos)  # type: ignore[misc]
        close = "]" + "=" * eqs + "]"
        end = text.find(close, start)
        if end < 0:
            raise TableError(f"{path}:{line}: unterminated bracket argument or comment")
        content = text[start:end]
        line += text.count("\n", pos, end + len(close))
        return end + len(close), content

    def skip_blank(pos: int) -> int | None:
        """The position past the space, newline or comment at pos (counting lines), or None
        when none starts there."""
        nonlocal line
        c = text[pos]
        if c == "\n":
            line += 1
            return pos + 1
        if c in " \t\r":
            return pos + 1
        if c == "#":
            if pos + 1 < n and text[pos + 1] == "[" and bracket_end(pos + 1):
                return skip_bracket(pos + 1)[0]
            while pos < n and text[pos] != "\n":
                pos += 1
            return pos
        return None

    while i < n:
        c = text[i]
        if (past := skip_blank(i)) is not None:
            i = past
        elif c.isalpha() or c == "_":
            m = re.match(r"[A-Za-z_][A-Za-z0-9_]*", text[i:])
            assert m
            name = m.group(0)
            cmd_line = line
            i += m.end()
            while i < n and text[i] in " \t":
                i += 1
            if i >= n or text[i] != "(":
                raise TableError(f"{path}:{line}: expected '(' after {name}")
            i += 1
            args: list[Arg] = []
            depth = 0
            while True:
                if i >= n:
                    raise TableError(f"{path}:{cmd_line}: unterminated call to {name}")
                c = text[i]
                if (past := skip_blank(i)) is not None:
                    i = past
                elif c == "(":
                    depth += 1
                    i += 1
                elif c == ")":
                    if depth == 0:
                        i += 1
                        break
                    depth -= 1
                    i += 1
                elif c == '"':
                    j = i + 1
                    buf = []
                    while True:
                        if j >= n:
                            raise TableError(f"{path}:{line}: unterminated quoted argument")
                        d = text[j]
                        if d == "\\" and j + 1 < n:
                            buf.append(text[j:j + 2])
                            if text[j + 1] == "\n":
                                line += 1
                            j += 2
                            continue
                        if d == '"':
                            break
                        if d == "\n":
                            line += 1
                        buf.append(d)
                        j += 1
                    args.append(Arg("".join(buf), True))
                    i = j + 1
                elif c == "[" and bracket_end(i):
                    i, content = skip_bracket(i)
                    args.append(Arg(content, True))
                else:
                    j = i
                    buf = []
                    while j < n:
                        d = text[j]
                        if d == "\\" and j + 1 < n:
                            buf.append(text[j:j + 2])
                            j += 2
                            continue
                        if d in " \t\r\n()#\"":
                            break
                        buf.append(d)
                        j += 1
                    args.append(Arg("".join(buf), False))
                    i = j
            commands.append(Command(name.lower(), args, cmd_line))
        else:
            raise TableError(f"{path}:{line}: unexpected character {c!r}")
    return commands


def expand(args: list[Arg], variables: dict[str, list[str]]) -> list[str]:
    """Expand ${var} references; unquoted arguments split on ';' as CMake does."""
    out: list[str] = []
    for a in args:
        def sub(m: re.Match[str]) -> str:
            return ";".join(variables.get(m.group(1), []))
        prev = None
        s = a.text
        while prev != s:  # nested ${${x}} references, innermost first
            prev = s
            s = VAR_RE.sub(sub, s)
        if a.quoted:
            out.append(s)
        else:
            out.extend(p for p in s.split(";") if p != "")
    return out


# ---------------------------------------------------------------------------------------
# The module table.

@dataclass
class Module:
    target: str
    folder: str
    line: int
    kind: str  # "netsph_module", "add_library", "add_executable"
    deps: list[str] = field(default_factory=list)
    private_deps: list[str] = field(default_factory=list)


def read_table(cmake_path: Path, src_root: Path) -> tuple[dict[str, Module], list[str]]:
    """Return (modules by target, problems) from src/CMakeLists.txt."""
    text = cmake_path.read_text(encoding="utf-8")
    rel = "src/CMakeLists.txt"
    commands = lex_cmake(text, rel)
    variables: dict[str, list[str]] = {}
    globs: dict[str, list[str]] = {}  # variable -> glob patterns
    modules: dict[str, Module] = {}
    # (target, keyword, items, line): link calls, resolved once every module is known
    links: list[tuple[str, str, list[str], int]] = []
    problems: list[str] = []

    block_depth = 0  # inside function()/macro() bodies nothing runs at definition time
    for cmd in commands:
        if cmd.name in ("function", "macro"):
            block_depth += 1
            continue
        if cmd.name in ("endfunction", "endmacro"):
            block_depth -= 1
            continue
        if block_depth:
            continue
        args = expand(cmd.args, variables)
        if cmd.name == "set" and args:
            vals = [v for v in args[1:]]
            # set(var value CACHE type doc [FORCE]) / set(var value PARENT_SCOPE)
            if "CACHE" in vals:
                vals = vals[:vals.index("CACHE")]
            vals = [v for v in vals if v != "PARENT_SCOPE"]
            variables[args[0]] = [p for v in vals for p in v.split(";") if p]
        elif cmd.name == "unset" and args:
            variables.pop(args[0], None)
        elif cmd.name == "list" and len(args) >= 2:
            op, var, items = args[0].upper(), args[1], args[2:]
            cur = variables.setdefault(var, [])
            if op == "APPEND":
                cur.extend(items)
            elif op == "PREPEND":
                variables[var] = items + cur
            elif op == "REMOVE_ITEM":
                variables[var] = [v for v in cur if v not in items]
        elif cmd.name == "file" and args and args[0].upper() in ("GLOB", "GLOB_RECURSE"):
            if len(args) >= 2:
                pats = [a for a in args[2:] if a.upper() not in ("CONFIGURE_DEPENDS", "LIST_DIRECTORIES", "RELATIVE", "FOLLOW_SYMLINKS")]
                globs[args[1]] = pats
                variables[args[1]] = []  # what the glob finds is not needed here
        elif cmd.name == "netsph_module":
            if len(args) < 2:
                problems.append(f"{rel}:{cmd.line}: netsph_module call without a target and folder")
                continue
            name, folder = args[0], args[1].strip("/")
            mod = Module(name, folder, cmd.line, "netsph_module")
            bucket = None
            for a in args[2:]:
                if a == "DEPS":
                    bucket = mod.deps
                elif a == "PRIVATE_DEPS":
                    bucket = mod.private_deps
                elif bucket is None:
                    problems.append(f"{rel}:{cmd.line}: netsph_module({name}): stray argument {a!r}")
                else:
                    bucket.append(a)
            if name in modules:
                problems.append(f"{rel}:{cmd.line}: target {name} declared twice (first at line {modules[name].line})")
            modules[name] = mod
        elif cmd.name in ("add_library", "add_executable") and cmd.args:
            raw_name = args[0] if args else ""
            if not (raw_name == "netsph" or raw_name.startswith("netsph_")):
                continue
            folders = set()
            for a in cmd.args[1:]:
                for var in VAR_RE.findall(a.text):
                    for pat in globs.get(var, []):
                        m = GLOB_FOLDER_RE.search(pat)
                        if m:
                            folders.add(m.group(1).strip("/"))
                m = GLOB_FOLDER_RE.search(a.text) or re.search(r"(?:^|/)netsph/(.+)/[^/]+\.\w+$", a.text)
                if m and "${" not in m.group(1):
                    folders.add(m.group(1).strip("/"))
            if not folders:
                # A library with no sources under src/netsph (netsph_flags is in the top-level
                # file, but any such helper here) is not a module.
                continue
            if len(folders) > 1:
                problems.append(f"{rel}:{cmd.line}: {cmd.name}({raw_name}) takes sources from several folders: {sorted(folders)}")
            if raw_name in modules:
                problems.append(f"{rel}:{cmd.line}: target {raw_name} declared twice (first at line {modules[raw_name].line})")
            modules[raw_name] = Module(raw_name, sorted(folders)[0], cmd.line, cmd.name)
        elif cmd.name == "target_link_libraries" and args:
            target, rest = args[0], args[1:]
            keyword = "PUBLIC"  # the plain signature is transitive
            items: list[str] = []
            for a in rest:
                if a in ("PUBLIC", "PRIVATE", "INTERFACE", "LINK_PUBLIC", "LINK_PRIVATE", "LINK_INTERFACE_LIBRARIES"):
                    if items:
                        links.append((target, keyword, items, cmd.line))
                    keyword = {"LINK_PUBLIC": "PUBLIC", "LINK_PRIVATE": "PRIVATE",
                               "LINK_INTERFACE_LIBRARIES": "INTERFACE"}.get(a, a)
                    items = []
                else:
                    items.append(a)
            if items:
                links.append((target, keyword, items, cmd.line))

    for target, keyword, items, line in links:
        mod = modules.get(target)
        if mod is None:
            continue
        if mod.kind == "add_executable" or keyword == "PRIVATE":
            mod.private_deps.extend(items)
        else:
            mod.deps.extend(items)

    # Keep only netsph modules as dependencies; a netsph_* name that is no module is a typo.
    for mod in modules.values():
        has_cpp = any((src_root / "netsph" / mod.folder).glob("*.cpp"))
        if mod.kind == "netsph_module" and not has_cpp and mod.private_deps:
            # netsph_module makes an INTERFACE library and drops PRIVATE_DEPS.
            nets = [d for d in mod.private_deps if d in modules]
            if nets:
                problems.append(
                    f"{rel}:{mod.line}: {mod.target} has no .cpp files, so netsph_module makes it an "
                    f"INTERFACE library and drops its PRIVATE_DEPS {' '.join(nets)}; declare them as DEPS")
            mod.private_deps = []
        for lst in (mod.deps, mod.private_deps):
            for d in lst:
                if d not in modules and re.fullmatch(r"netsph_[A-Za-z0-9_]+", d) and d != "netsph_flags":
                    problems.append(f"{rel}:{mod.line}: {mod.target} links {d}, which no module declares")
            kept = []
            for d in lst:
                if d in modules and d != mod.target and d not in kept:
                    kept.append(d)
            lst[:] = kept

    folders: dict[str, str] = {}
    for mod in modules.values():
        if mod.folder in folders:
            problems.append(f"{rel}:{mod.line}: folder {mod.folder} is declared by both {folders[mod.folder]} and {mod.target}")
        else:
            folders[mod.folder] = mod.target
        if not (src_root / "netsph" / mod.folder).is_dir():
            problems.append(f"{rel}:{mod.line}: {mod.target} declares folder src/netsph/{mod.folder}, which does not exist")
    return modules, problems


def allowed_modules(modules: dict[str, Module]) -> dict[str, set[str]]:
    """For each target, the targets whose headers it may include."""
    public_closure: dict[str, set[str]] = {}

    def closure(t: str) -> set[str]:
        # t and everything t reaches through DEPS (public), transitively
        if t in public_closure:
            return public_closure[t]
        seen: set[str] = set()
        stack = [t]
        while stack:
            x = stack.pop()
            if x in seen:
                continue
            seen.add(x)
            stack.extend(modules[x].deps)
        public_closure[t] = seen
        return seen

    allowed: dict[str, set[str]] = {}
    for t, mod in modules.items():
        ok = {t}
        for d in mod.deps + mod.private_deps:
            ok |= closure(d)
        allowed[t] = ok
    return allowed


# ---------------------------------------------------------------------------------------
# The includes.

def strip_block_comments(text: str) -> str:
    """Blank /* */ comments, keeping newlines so line numbers stay right. A `/*` inside a line
    comment or a string or character literal starts nothing (`// snapshots/*.h5` must not
    hide the includes below it), so those are matched first and kept as they are; an include
    is matched only at the start of a line, so line comments need no other care."""
    token = re.compile(r'//[^\n]*|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|/\*.*?\*/', re.DOTALL)

    def blank(m: re.Match[str]) -> str:
        if not m.group(0).startswith("/*"):
            return m.group(0)
        return "".join("\n" if ch == "\n" else " " for ch in m.group(0))
    return token.sub(blank, text)


def module_of(path_under_netsph: str, folders: list[tuple[str, str]]) -> str | None:
    """Target owning netsph/<path>, by longest matching folder (folders sorted longest first)."""
    for folder, target in folders:
        if path_under_netsph.startswith(folder + "/"):
            return target
    return None


def check(root: Path) -> int:
    src_root = root / "src"
    netsph_root = src_root / "netsph"
    cmake_path = src_root / "CMakeLists.txt"
    if not cmake_path.is_file() or not netsph_root.is_dir():
        print(f"check_layering: {root} has no src/CMakeLists.txt and src/netsph/", file=sys.stderr)
        return 2
    try:
        modules, problems = read_table(cmake_path, src_root)
    except TableError as e:
        print(f"check_layering: {e}", file=sys.stderr)
        return 2
    if not modules:
        print("check_layering: no module found in src/CMakeLists.txt", file=sys.stderr)
        return 2
    allowed = allowed_modules(modules)
    folders = sorted(((m.folder, t) for t, m in modules.items()), key=lambda ft: -len(ft[0]))
    folder_of = {t: m.folder for t, m in modules.items()}
    declared = {m.folder for m in modules.values()}

    files = sorted(p for p in netsph_root.rglob("*") if p.is_file() and p.suffix in SOURCE_SUFFIXES)
    undeclared: dict[str, int] = {}
    for p in files:
        folder = p.parent.relative_to(netsph_root).as_posix()
        if folder not in declared:
            undeclared[folder] = undeclared.get(folder, 0) + 1
    for folder, count in sorted(undeclared.items()):
        problems.append(f"src/netsph/{folder}/: {count} source/header file(s) in a folder that no module "
                        f"in src/CMakeLists.txt declares")

    n_includes = 0
    for p in files:
        rel_file = p.relative_to(root).as_posix()
        folder = p.parent.relative_to(netsph_root).as_posix()
        owner = module_of(folder + "/", folders) if folder in declared else None
        text = strip_block_comments(p.read_text(encoding="utf-8", errors="replace"))
        for m in INCLUDE_RE.finditer(text):
            delim, inc = m.group(1), m.group(2).strip()
            line = text.count("\n", 0, m.start()) + 1
            if inc.startswith("netsph/"):
                target_path = src_root / inc
                under = inc[len("netsph/"):]
            elif delim == '"':
                # A relative include (#include "x.hpp", "../sph/x.hpp") found next to the file.
                cand = (p.parent / inc).resolve()
                try:
                    under = cand.relative_to(netsph_root.resolve()).as_posix()
                except ValueError:
                    continue
                if not cand.is_file():
                    continue  # found elsewhere on the include path, not a netsph header
                target_path = cand
            else:
                continue
            n_includes += 1
            if not target_path.is_file():
                problems.append(f"{rel_file}:{line}: includes {inc}, which does not exist")
                continue
            inc_module = module_of(under, folders)
            if inc_module is None:
                problems.append(f"{rel_file}:{line}: includes {inc}, which is in no declared module")
                continue
            if owner is None:
                continue  # the file's own folder is already reported as undeclared
            if inc_module not in allowed[owner]:
                problems.append(f"{rel_file}:{line}: includes {inc} (module {folder_of[inc_module]}), "
                                f"but {owner} does not link {inc_module}")

    if problems:
        for pr in problems:
            print(pr)
        print(f"check_layering: {len(problems)} problem(s) ({len(modules)} modules, {len(files)} files, "
              f"{n_includes} includes checked)", file=sys.stderr)
        return 1
    print(f"check_layering: ok: {len(modules)} modules, {len(files)} files, {n_includes} netsph includes checked")
    return 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent,
                    help="repository to check (default: the one holding this script)")
    ap.add_argument("--table", action="store_true", help="print the module table read from src/CMakeLists.txt")
    a = ap.parse_args()
    root = a.root.resolve()
    if a.table:
        try:
            modules, problems = read_table(root / "src" / "CMakeLists.txt", root / "src")
        except TableError as e:
            print(f"check_layering: {e}", file=sys.stderr)
            return 2
        for m in modules.values():
            print(f"{m.target:24} {m.folder:16} DEPS {' '.join(m.deps) or '-'}  PRIVATE_DEPS {' '.join(m.private_deps) or '-'}")
        for pr in problems:
            print(pr)
        return 1 if problems else 0
    return check(root)


if __name__ == "__main__":
    sys.exit(main())
