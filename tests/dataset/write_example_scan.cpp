// Writes matgeom's example scan as Replica lays out a scan: the file the scan tests put objects
// back into. Usage: write_example_scan OUT.ply
#include <cstdio>
#include <exception>

#include "matgeom/builtin/example_scan.h"
#include "support/replica_ply.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_example_scan OUT.ply\n");
    return 2;
  }
  try {
    write_replica_ply(matgeom::example_scan(), argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_example_scan: %s\n", e.what());
    return 1;
  }
  return 0;
}
