#!/usr/bin/env bash
# koppel as an installed package, checked as its users meet it (ctest `packaging`, CI):
#   check.sh BUILD_DIR SOURCE_DIR WORK_DIR PYTHON PYTHON_DIR
# installs BUILD_DIR into WORK_DIR/prefix, then
# - the installed `koppel` finds its catalog without --catalog, takes a catalog id for a file
#   (`koppel analyze crank-rocker`), and prints the version;
# - the installed headers pull in no header of Ceres, glog or yaml-cpp, nor any private one;
# - tests/packaging/cpp (find_package, koppel::koppel) computes the slider-crank's stroke;
# - tests/packaging/analysis_only (koppel::analysis) does too, and neither its dependencies, nor
#   the libraries it loads, nor the code linked into it is Ceres, glog or yaml-cpp;
# - the installed koppel loads neither Ceres nor cairo at start-up (they are modules, lib/koppel),
#   nor muparser to analyze a catalog entry;
# - with the Python module (PYTHON_DIR, relative to the prefix; empty: not built)
#   tests/packaging/python/stroke.py does the same against the installed module;
# - the C++ and Python examples of docs/library.md ("C++ and Python API") run as written.
set -euo pipefail
build=$1 source=$2 work=$3 python=$4 python_dir=${5:-}
prefix=$work/prefix
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
echo "installed: $(du -sh "$prefix" | cut -f1) in $(find "$prefix" -type f | wc -l) files under $prefix"
unset KOPPEL_CATALOG
private='ceres|glog|gflags|yaml-cpp|muParser|fmt/|nlohmann|CLI/'

fail() { echo "FAILED: $*" >&2; exit 1; }

# the installed tool: version and catalog from the prefix
version=$("$prefix/bin/koppel" --version)
echo "$version"
(cd "$work" && "$prefix/bin/koppel" catalog find --links 4 --prismatic 1) > "$work/find.txt" || fail "koppel catalog find"
grep -q slider-crank-offset "$work/find.txt" || fail "the installed koppel does not find its catalog"
installed_catalog() {  # PREFIX: the installed koppel reads its entries from PREFIX/share/koppel/catalog
  (cd "$work" && "$1/bin/koppel" catalog show slider-crank-offset) > "$work/show.txt" || fail "koppel catalog show"
  grep -q "^file: *$1/share/koppel/catalog/slider-crank-offset.yaml" "$work/show.txt" ||
    fail "the koppel installed in $1 does not read the catalog installed with it"
  # a catalog id where a file is expected, outside the source tree (issue 22, item 9): the entry
  # installed with it, the same table as for the entry's file
  (cd "$work" && "$1/bin/koppel" analyze crank-rocker --step 30) > "$work/by_id.csv" || fail "$1/bin/koppel analyze crank-rocker"
  (cd "$work" && "$1/bin/koppel" analyze "$1/share/koppel/catalog/crank-rocker.yaml" --step 30) > "$work/by_file.csv" ||
    fail "$1/bin/koppel analyze $1/share/koppel/catalog/crank-rocker.yaml"
  cmp -s "$work/by_id.csv" "$work/by_file.csv" || fail "analyze crank-rocker differs from analyze of the installed entry's file"
}
installed_catalog "$prefix"

# installed headers: every one included at once, the include closure listed by the preprocessor
headers=$(cd "$prefix/include" && find koppel -name '*.hpp' | sort)
for h in $headers; do echo "#include <$h>"; done > "$work/all_headers.cpp"
c++ -std=c++20 -M -I"$prefix/include" -I/usr/include/eigen3 "$work/all_headers.cpp" > "$work/all_headers.d"
if grep -Eo "[^ ]*($private)[^ ]*" "$work/all_headers.d"; then fail "installed headers include a private dependency"; fi
echo "installed headers: $(echo "$headers" | wc -w), none includes Ceres, glog, yaml-cpp, muparser, fmt, json or CLI11"

consumer() {  # NAME: configure, build and run tests/packaging/NAME against the prefix
  cmake -S "$source/tests/packaging/$1" -B "$work/$1" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release > "$work/$1.log"
  cmake --build "$work/$1" >> "$work/$1.log" || { cat "$work/$1.log"; fail "building $1"; }
}

consumer cpp
"$work/cpp/stroke" > "$work/cpp.out" || { cat "$work/cpp.out"; fail "tests/packaging/cpp"; }
cat "$work/cpp.out"
grep -q "catalog $prefix/share/koppel/catalog" "$work/cpp.out" || fail "the library does not find the catalog installed with it"

consumer analysis_only
"$work/analysis_only/analysis_only" || fail "tests/packaging/analysis_only"
# compile time: the headers the program's compilation read (the compiler's depfile)
depfile=$(find "$work/analysis_only" -name 'analysis_only.cpp.o.d')
[ -n "$depfile" ] || fail "no depfile of analysis_only.cpp"
if grep -Eo "[^ ]*($private)[^ ]*" "$depfile"; then fail "analysis_only compiled with a private dependency's header"; fi
# link and run time: its own dependencies, every library the loader maps for it, and the code
# linked into it from koppel's static libraries
readelf -d "$work/analysis_only/analysis_only" | grep NEEDED > "$work/needed.txt" || true
ldd "$work/analysis_only/analysis_only" > "$work/ldd.txt"
if grep -Ei 'ceres|glog|yaml|muparser|koppel' "$work/needed.txt" "$work/ldd.txt"; then fail "analysis_only links Ceres, glog, yaml-cpp, muparser or a koppel library"; fi
nm -C --defined-only "$work/analysis_only/analysis_only" > "$work/symbols.txt"
grep -q 'koppel::FindDeadCentres(' "$work/symbols.txt" || fail "analysis_only does not hold koppel's analysis"
# Ceres lives in the module libkoppel_ceres.so, loaded by synthesis on its first fit; nothing of
# synthesis, the catalog or yaml-cpp is linked into a program that only analyses
if grep -m1 -E 'ceres::|YAML::|koppel::Fit\(|koppel::Catalog::Load' "$work/symbols.txt"; then
  fail "analysis_only holds Ceres, yaml-cpp, synthesis or the catalog"
fi
echo "analysis_only: $(wc -l < "$work/ldd.txt") libraries loaded, none of Ceres, glog, yaml-cpp or koppel"
# the installed koppel maps Ceres, cairo, muparser (with libgomp) and Google Benchmark only with
# the commands (the files) that need them
ldd "$prefix/bin/koppel" > "$work/koppel_ldd.txt"
if grep -Ei 'ceres|glog|cholmod|lapack|cairo|X11|slvs|muparser|gomp|benchmark|koppel' "$work/koppel_ldd.txt"; then
  fail "the installed koppel loads a heavy library at start-up"
fi
for module in ceres gif muparser bench; do
  [ -n "$(find "$prefix" -path "*/koppel/libkoppel_$module.so")" ] || fail "the module libkoppel_$module.so is not installed"
done
echo "koppel: $(wc -l < "$work/koppel_ldd.txt") libraries loaded at start-up"
# nor muparser (with libgomp) for `koppel analyze` of an entry whose mechanism part holds numbers
# and names alone: its card's formulas are the catalog commands' to parse (issue 25); the loader's
# own trace (LD_DEBUG=files) names every library mapped, at start or by dlopen
(cd "$work" && LD_DEBUG=files "$prefix/bin/koppel" analyze crank-rocker) > /dev/null 2> "$work/analyze_libs.txt" ||
  fail "koppel analyze crank-rocker"
grep -q 'libstdc++' "$work/analyze_libs.txt" || fail "LD_DEBUG=files traced no library"
if grep -Ei 'muparser|gomp' "$work/analyze_libs.txt"; then fail "koppel analyze crank-rocker maps muparser"; fi

# docs/library.md's examples, as written
readme_block() {  # LANGUAGE: the first fenced block of that language on the page
  awk -v lang="$1" '$0 == "```" lang {inside = 1; next}
                    inside && /^```/ {exit}
                    inside {print}' "$source/docs/library.md"
}
mkdir -p "$work/readme_cpp"
readme_block cpp > "$work/readme_cpp/example.cpp"
[ -s "$work/readme_cpp/example.cpp" ] || fail "docs/library.md has no C++ example"
readme_block cmake > "$work/readme_cpp/CMakeLists.txt"
[ -s "$work/readme_cpp/CMakeLists.txt" ] || fail "docs/library.md has no CMakeLists.txt"
cmake -S "$work/readme_cpp" -B "$work/readme_cpp/build" -DCMAKE_PREFIX_PATH="$prefix" > "$work/readme_cpp.log"
cmake --build "$work/readme_cpp/build" >> "$work/readme_cpp.log" || { cat "$work/readme_cpp.log"; fail "building docs/library.md's C++ example"; }
(cd "$source" && "$work/readme_cpp/build/example") > "$work/readme_cpp.out" || fail "docs/library.md's C++ example"
echo "docs/library.md C++ example:" && cat "$work/readme_cpp.out"

if [ -n "$python_dir" ]; then
  export PYTHONPATH="$prefix/$python_dir"
  (cd "$work" && KOPPEL_PREFIX="$prefix" "$python" "$source/tests/packaging/python/stroke.py") || fail "tests/packaging/python/stroke.py"
  readme_block python > "$work/readme_example.py"
  [ -s "$work/readme_example.py" ] || fail "docs/library.md has no Python example"
  (cd "$source" && "$python" "$work/readme_example.py") > "$work/readme_python.out" || fail "docs/library.md's Python example"
  echo "docs/library.md Python example:" && cat "$work/readme_python.out"
fi
# an installed tree moved elsewhere still finds its libraries and its catalog
mv "$prefix" "$work/moved" && installed_catalog "$work/moved"
"$work/moved/bin/koppel" --version > /dev/null || fail "the moved koppel does not start"
echo "packaging: all passed"
