#!/bin/sh
# Installs the build into a scratch prefix and builds programs against it
# the ways README describes: CMake's find_package(gpdr CONFIG) (C with
# libtriangle.so and libtriangle.a, C++ with libgpdr.a) and pkg-config
# (triangle.pc, gpdr.pc); then runs each one.
#   run.sh BUILD_DIR
set -eu
build=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
prefix=$scratch/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null

cmake -S "$here" -B "$scratch/cmake" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$scratch/cmake" >/dev/null
"$scratch/cmake/consumer_c"
"$scratch/cmake/consumer_c_static"
"$scratch/cmake/consumer_cpp"

pcdir=$(dirname "$(find "$prefix" -name triangle.pc)")
export PKG_CONFIG_PATH="$pcdir"
cc -o "$scratch/pc_c" "$here/consumer.c" $(pkg-config --cflags --libs triangle)
LD_LIBRARY_PATH=$(pkg-config --variable=libdir triangle) "$scratch/pc_c"
c++ -std=c++20 -o "$scratch/pc_cpp" "$here/consumer.cpp" $(pkg-config --cflags --libs gpdr)
"$scratch/pc_cpp"
echo "consumers: CMake and pkg-config builds work"
