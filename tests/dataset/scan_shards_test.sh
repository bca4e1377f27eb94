#!/usr/bin/env bash
# The shards test on a configuration that puts objects back in a scan: the example scan is written
# beside a copy of the configuration first (the scan is made by the tests, not kept in the tree).
# Usage: scan_shards_test.sh MAKE_DATASET CONFIG OUTPUT_FOLDER WRITE_EXAMPLE_SCAN
set -u
here=$(dirname "$0")
rm -rf "$3"
mkdir -p "$3/config/scan"
cp "$2" "$3/config/"
"$4" "$3/config/scan/mesh_semantic.ply" || { echo "could not write the example scan"; exit 1; }
exec bash "$here/shards_test.sh" "$1" "$3/config/$(basename "$2")" "$3/run"
