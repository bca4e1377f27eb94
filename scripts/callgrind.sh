#!/usr/bin/env bash
# Counts a program's instructions with callgrind, for comparing two versions of a hot path:
#   bash scripts/callgrind.sh OUT.callgrind PROGRAM [ARGS...]
# (more valgrind options in $CALLGRIND_OPTIONS). A render's work runs on TBB's threads, where
# --toggle-collect on the calling function sees nothing: to count what a sample costs, count two
# runs that differ only in samples per pixel and divide the difference.
# valgrind 3.19 cannot decode the RDTSCP that libhwy's initialiser executes, and libhwy arrives
# through OpenImageIO's libjxl. Nothing here decodes JPEG XL, so the program runs against a
# stand-in libhwy.so.1 that defines the five symbols libjxl imports and does nothing.
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: bash scripts/callgrind.sh OUT.callgrind PROGRAM [ARGS...]" >&2
  exit 2
fi
out=$1
shift
stub=$(mktemp -d)
trap 'rm -rf "$stub"' EXIT
cat > "$stub/hwy.c" <<'C'
void deleter(void) __asm__("_ZN3hwy14AlignedDeleter18DeleteAlignedArrayEPvPFvS1_S1_ES1_PFvS1_mE");
void deleter(void) {}
void* chosen(void) __asm__("_ZN3hwy15GetChosenTargetEv");
void* chosen(void) { return 0; }
void free_aligned(void) __asm__("_ZN3hwy16FreeAlignedBytesEPKvPFvPvS2_ES2_");
void free_aligned(void) {}
long supported(void) __asm__("_ZN3hwy16SupportedTargetsEv");
long supported(void) { return 0; }
void* allocate(void) __asm__("_ZN3hwy20AllocateAlignedBytesEmPFPvS0_mES0_");
void* allocate(void) { return 0; }
C
echo 'HWY_0 { global: _ZN3hwy*; local: *; };' > "$stub/hwy.map"
gcc -shared -fPIC -o "$stub/libhwy.so.1" -Wl,-soname,libhwy.so.1 -Wl,--version-script="$stub/hwy.map" "$stub/hwy.c"
LD_LIBRARY_PATH="$stub${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
  valgrind --tool=callgrind --callgrind-out-file="$out" ${CALLGRIND_OPTIONS:-} "$@"
