#!/usr/bin/env python3
"""The include graph of core/, io/, frontend/, cli/, python/ and filter_fcvt/ against the declared layers (issue 51).

Reads every `#include "..."` of the C++ files there and fails, listing each, on
  - an include against the layers: a file may include files of its own layer and of the layers
    its layer uses (LAYER_USES, transitively), nothing else;
  - a cycle between modules. A module is a header and the .cpp files that implement it: x.h with
    x.cpp, and the files IMPLEMENTS puts with a header (a .cpp without a header of its own must be
    there, so that no implementation hides from the graph).
Usage: check_include_layers.py [SOURCE_DIR] [--graph] (--graph prints the module graph too).
"""
import fnmatch
import os
import re
import sys

# The layers, lowest first; a file is in the layer of the first pattern that matches its path.
FILE_LAYERS = [
    # Base: the mesh, errors, progress, small utilities, and the small headers of types that the
    # stages share with remesh()'s parameters and result (x_types.h, x_params.h).
    ("core/mesh.*", "base"),
    ("core/errors.*", "base"),
    ("core/progress.h", "base"),
    ("core/disjoint_sets.h", "base"),
    ("core/parallel_sort.h", "base"),
    ("core/triple_hash.h", "base"),
    ("core/huge_pages.*", "base"),
    ("core/thread_budget.*", "base"),
    ("core/mesh_texture.h", "base"),
    ("core/texture_image.h", "base"),
    ("core/*_types.h", "base"),
    # The contract of remesh(), what the front ends include: its parameters, result and limits.
    ("core/remesh.h", "contract"),
    ("core/remesh_params.h", "contract"),
    ("core/remesh_limits.*", "contract"),
    ("core/remesh_result.h", "contract"),
    ("core/remesh_presets.h", "contract"),
    ("core/*_params.h", "base"),
    # The orchestration: remesh() running the stages, and the selection-only remeshing over it.
    ("core/remesh*", "orchestration"),
    ("core/region*", "region"),
    # The stages (field, interpolation, rvd, energy, optimize, rdt, valence, features, metrics,
    # repair, thin parts, ...) and the geometry they share.
    ("core/*", "stages"),
    ("io/*", "io"),
    # What the CLI and the Python module share: options as RemeshParams, results as report JSON.
    ("frontend/*", "frontend"),
    ("cli/*", "cli"),
    ("python/*", "python"),
    ("filter_fcvt/*", "filter_fcvt"),
]

# What each layer may include besides itself (and, transitively, what those use).
LAYER_USES = {
    "base": [],
    "contract": ["base"],
    "stages": ["base"],
    "orchestration": ["contract", "stages"],
    "region": ["orchestration"],
    "io": ["stages"],
    "frontend": ["region"],
    "cli": ["frontend", "region", "io"],
    "python": ["frontend", "region", "io"],
    "filter_fcvt": ["region", "io"],
}

# Files that implement a header of another name (their module is that header's); x.cpp with an
# x.h is always x's.
IMPLEMENTS = [
    ("core/rvd_*", "core/rvd.h"),  # rvd_impl.h and its parts rvd_clip.cpp, rvd_neighbours.cpp
    ("core/region_*.cpp", "core/region.h"),
    ("core/remesh_*.cpp", "core/remesh_stages.h"),
    ("core/valence/apply.cpp", "core/valence/operations.h"),
    ("core/valence/chains.cpp", "core/valence/operations.h"),
    ("io/read_*.cpp", "io/formats.h"),
    ("io/write_*.cpp", "io/formats.h"),
    ("io/mesh_format.h", "io/mesh_io.h"),  # checkMeshExtension, defined in mesh_io.cpp
    ("cli/command_*.cpp", "cli/commands.h"),
    ("filter_fcvt/filter_remesh.cpp", "filter_fcvt/filter_run.h"),
    ("python/bind_*.cpp", "python/bindings.h"),
]
# .cpp files without a header that nothing includes: modules of their own.
ENTRY_POINTS = {"cli/main.cpp", "python/module.cpp"}

# Known exceptions: include edges ignored, both as layer violations and in the cycle search.
KNOWN_EXCEPTIONS = set()

ROOTS = ["core", "io", "frontend", "cli", "python", "filter_fcvt"]
# Where a quoted include is looked for after the including file's folder (CMake's include
# directories of each target); an include found in none is a library's (vcglib, MeshLab, Qt).
SEARCH = {
    "core": ["core"],
    "io": ["io", "core"],
    "frontend": ["frontend", "core"],
    "cli": ["cli", "frontend", "core", "io"],
    "python": ["python", "frontend", "core", "io"],
    "filter_fcvt": ["filter_fcvt", "core", "io"],
}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def source_files(top):
    files = []
    for root in ROOTS:
        for folder, _, names in os.walk(os.path.join(top, root)):
            for name in names:
                if name.endswith((".h", ".cpp")):
                    files.append(os.path.relpath(os.path.join(folder, name), top).replace(os.sep, "/"))
    return sorted(files)


def includes(top, path):
    """(line, included path) of each quoted include of `path` that is a file of the tree."""
    found = []
    own = os.path.dirname(path)
    dirs = [own] + SEARCH[path.split("/")[0]]
    with open(os.path.join(top, path), encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            for d in dirs:
                candidate = os.path.normpath(os.path.join(d, m.group(1))).replace(os.sep, "/")
                if os.path.isfile(os.path.join(top, candidate)):
                    found.append((number, candidate))
                    break
    return found


def first_match(path, table):
    return next((value for pattern, value in table if fnmatch.fnmatch(path, pattern)), None)


def uses_closure():
    closure = {}
    for layer in LAYER_USES:
        seen, todo = {layer}, [layer]
        while todo:
            for used in LAYER_USES[todo.pop()]:
                if used not in seen:
                    seen.add(used)
                    todo.append(used)
        closure[layer] = seen
    return closure


def module_of(path, files, problems):
    stem, ext = os.path.splitext(path)
    if ext == ".cpp" and stem + ".h" in files:
        return stem
    header = first_match(path, IMPLEMENTS)
    if header:
        return header[: -len(".h")]
    if ext == ".cpp" and path not in ENTRY_POINTS:
        problems.append(f"{path}: no header of its own: add the header it implements to IMPLEMENTS")
    return stem


def cycles(graph):
    """The strongly connected components of more than one module (Tarjan), each sorted."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    sys.setrecursionlimit(10000)
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    top = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    files = source_files(top)
    file_set = set(files)
    allowed = uses_closure()
    problems = []
    graph, edges_of = {}, {}  # module -> modules it includes; (module, module) -> a file edge
    excepted = set()
    for path in files:
        layer = first_match(path, FILE_LAYERS)
        module = module_of(path, file_set, problems)
        graph.setdefault(module, set())
        for number, target in includes(top, path):
            if (path, target) in KNOWN_EXCEPTIONS:
                excepted.add((path, target))
                continue
            target_layer = first_match(target, FILE_LAYERS)
            if target_layer not in allowed[layer]:
                problems.append(f"{path}:{number}: {layer} includes {target} ({target_layer})")
            target_module = module_of(target, file_set, [])
            if target_module != module:
                graph[module].add(target_module)
                edges_of.setdefault((module, target_module), f"{path} -> {target}")
    for component in cycles(graph):
        members = set(component)
        inside = [edges_of[(a, b)] for a in component for b in sorted(graph[a]) if b in members]
        problems.append("include cycle between " + ", ".join(component) + ": " + "; ".join(inside))
    for source, target in sorted(KNOWN_EXCEPTIONS - excepted):
        print(f"note: known exception {source} -> {target} is no include any more: remove it from KNOWN_EXCEPTIONS")
    if "--graph" in sys.argv:
        for module in sorted(graph):
            print(module, "->", " ".join(sorted(graph[module])))
    for problem in problems:
        print(problem)
    print(f"{len(files)} files, {len(graph)} modules: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
