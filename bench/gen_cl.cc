// Writes benchmark CL files (bench/cl_generator.h): one large turning program, or many small ones.
//
//   gen_cl large OUT.cl [GOTOS [THREAD_EVERY]]   GOTOS GOTO lines (default 1000000), a THREAD/ON
//                                                sequence every THREAD_EVERY of them (3000)
//   gen_cl small DIR [COUNT [GOTOS]]             COUNT files DIR/part-NNNN.cl (1000) of GOTOS
//                                                GOTO lines each (2000), a thread every 1500
//   gen_cl threads OUT.cl [COUNT]                COUNT identical multi-pass threads (3000)
//   gen_cl binary IN.cl OUT.cl                   IN (APT text) as binary CLDATA, records as
//                                                APT360 writes them: a sequence number record
//                                                before each statement, up to 80 GOTO points
//                                                (240 words) in a motion record
#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

#include "cl_generator.h"
#include "reader/cldata_writer.h"
#include "support/diagnostics.h"

namespace {

// Writes what `generate(buf, flush)` makes to `path`.
template <typename Generate>
bool write_file(const std::string& path, Generate&& generate) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) {
    fmt::print(stderr, "gen_cl: cannot write {}: {}\n", path, std::strerror(errno));
    return false;
  }
  bool ok = true;
  std::string buf;
  generate(buf, [&](std::string& b) {
    ok = ok && std::fwrite(b.data(), 1, b.size(), f) == b.size();
    b.clear();
  });
  ok = std::fclose(f) == 0 && ok;
  if (!ok) fmt::print(stderr, "gen_cl: cannot write {}\n", path);
  return ok;
}

bool write_program(const std::string& path, std::string_view name, long gotos, long every) {
  return write_file(path, [&](std::string& buf, auto&& flush) {
    clpost::bench::turning_program(buf, flush, name, gotos, every);
  });
}

bool parse_long(const char* s, long& v) {
  const char* end = s + std::strlen(s);
  auto [p, ec] = std::from_chars(s, end, v);
  return ec == std::errc() && p == end && v >= 0;
}

bool write_binary(const char* in_path, const char* out_path) {
  std::string text;
  std::FILE* in = std::fopen(in_path, "rb");
  if (in == nullptr) {
    fmt::print(stderr, "gen_cl: cannot read {}: {}\n", in_path, std::strerror(errno));
    return false;
  }
  char chunk[1 << 16];
  for (size_t n; (n = std::fread(chunk, 1, sizeof chunk, in)) > 0;) text.append(chunk, n);
  std::fclose(in);
  clpost::Diagnostics diags(in_path);
  std::string bin;
  if (!clpost::cldata::encode_apt(text, diags, bin, {false, 80})) {
    fmt::print(stderr, "{}", diags.render_all());
    return false;
  }
  std::FILE* f = std::fopen(out_path, "wb");
  bool ok = f != nullptr && std::fwrite(bin.data(), 1, bin.size(), f) == bin.size();
  ok = f != nullptr && std::fclose(f) == 0 && ok;
  if (!ok) fmt::print(stderr, "gen_cl: cannot write {}\n", out_path);
  return ok;
}

int usage() {
  std::fputs(
      "usage: gen_cl large OUT.cl [GOTOS [THREAD_EVERY]]\n"
      "       gen_cl small DIR [COUNT [GOTOS]]\n"
      "       gen_cl threads OUT.cl [COUNT]\n"
      "       gen_cl milling OUT.cl [GOTOS]\n"
      "       gen_cl binary IN.cl OUT.cl\n",
      stderr);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string_view mode = argv[1];
  if (mode == "large") {
    long gotos = 1000000, every = 3000;
    if ((argc > 3 && !parse_long(argv[3], gotos)) || (argc > 4 && !parse_long(argv[4], every)))
      return usage();
    return write_program(argv[2], "BENCH-LARGE", gotos, every) ? 0 : 1;
  }
  if (mode == "small") {
    long count = 1000, gotos = 2000;
    if ((argc > 3 && !parse_long(argv[3], count)) || (argc > 4 && !parse_long(argv[4], gotos)))
      return usage();
    for (long n = 0; n < count; ++n) {
      if (!write_program(fmt::format("{}/part-{:04}.cl", argv[2], n), fmt::format("BENCH-{:04}", n),
                         gotos, 1500))
        return 1;
    }
    return 0;
  }
  if (mode == "threads") {
    long count = 3000;
    if (argc > 3 && !parse_long(argv[3], count)) return usage();
    return write_file(argv[2],
                      [&](std::string& buf, auto&& flush) {
                        clpost::bench::threads_program(buf, flush, "BENCH-THREADS", count);
                      })
               ? 0
               : 1;
  }
  if (mode == "milling") {
    long gotos = 200000;
    if (argc > 3 && !parse_long(argv[3], gotos)) return usage();
    return write_file(argv[2],
                      [&](std::string& buf, auto&& flush) {
                        clpost::bench::milling_program(buf, flush, "BENCH-MILLING", gotos);
                      })
               ? 0
               : 1;
  }
  if (mode == "binary" && argc == 4) return write_binary(argv[2], argv[3]) ? 0 : 1;
  return usage();
}
