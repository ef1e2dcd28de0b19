#include "cli/cli.h"

int main(int argc, char** argv) {
  return clpost::run_cli(argc, argv);
}
