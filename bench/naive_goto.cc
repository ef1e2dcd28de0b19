// The yardstick of issue #26: the least a post can do with a GOTO. Reads a CL file line by line
// with fgets, takes each GOTO's numbers with strtod and writes `G1 X… Z…` (X a diameter) with
// fprintf. bench/scale.sh times clpost's post against it.
//
//   naive_goto IN.cl OUT.nc
#include <cstdio>
#include <cstdlib>
#include <cstring>

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  std::FILE* in = std::fopen(argv[1], "r");
  std::FILE* out = std::fopen(argv[2], "w");
  if (in == nullptr || out == nullptr) return 1;
  char line[4096];
  while (std::fgets(line, sizeof line, in) != nullptr) {
    if (std::strncmp(line, "GOTO/", 5) != 0) continue;
    char* p = line + 5;
    const double x = std::strtod(p, &p);
    std::strtod(p + 1, &p);  // y
    const double z = std::strtod(p + 1, &p);
    std::fprintf(out, "G1 X%.3f Z%.3f\n", 2 * x, z);
  }
  return std::fclose(out) == 0 && std::fclose(in) == 0 ? 0 : 1;
}
