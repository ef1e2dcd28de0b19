// The reader reuses its buffers and the Statement's vectors: once warmed up it allocates nothing
// per line. Counted by replacing the global operator new in this test binary.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include "reader/cl_reader.h"

namespace {
std::atomic<size_t> g_allocations{0};
}  // namespace

void* operator new(size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, size_t) noexcept {
  std::free(p);
}

namespace clpost {
namespace {

TEST(ClReaderAllocations, NoneInSteadyState) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  std::string text;
  for (int i = 0; i < 30000; ++i) {
    text.clear();
    text += "GOTO / " + std::to_string(i) + ".5, -1.25, 3 $$ note\n";
    text += "CIRCLE / 1.0, 2.0, 3.0,  $\r\n   0.0, 0.0, 1.0, 5.0\r\n";
    text += "$$-> CSYS / 1.0, $\n     2.0\n";
    text += "pprint Some text\n";
    text += "tool path/OP_" + std::to_string(i % 10) + ",TOOL,MILL_0.120RAD\nRAPID\n\n";
    ASSERT_EQ(std::fwrite(text.data(), 1, text.size(), f), text.size());
  }
  std::rewind(f);
  Diagnostics diags("alloc.cl");
  ClReader reader(f, diags);
  Statement s;
  size_t count = 0;
  while (count < 5000 && reader.next(s)) ++count;  // warm-up: buffers reach their size
  const size_t before = g_allocations.load();
  while (reader.next(s)) ++count;
  const size_t during = g_allocations.load() - before;
  EXPECT_EQ(count, 30000u * 5);
  EXPECT_GT(before, 0u);  // the counter works
  EXPECT_EQ(during, 0u);
  EXPECT_EQ(diags.error_count(), 0u);
  std::fclose(f);
}

}  // namespace
}  // namespace clpost
