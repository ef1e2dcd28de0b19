#include "writer/block_buffer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace clpost {
namespace {

TEST(BlockBuffer, GrowsKeepingItsText) {
  BlockBuffer b;
  std::string expect;
  for (int i = 0; i < 1000; ++i) {  // 256 bytes at first, grown several times
    const std::string word = "X" + std::to_string(i) + " ";
    b.append(word);
    expect += word;
  }
  b.push_back('\n');
  expect += '\n';
  EXPECT_EQ(b.view(), expect);
  EXPECT_EQ(b.size(), expect.size());
}

TEST(BlockBuffer, OnlyWhatIsCommittedBelongsToIt) {
  BlockBuffer b;
  b.push_back('N');
  char* p = b.room(600);  // more than it has: grows, keeping the 'N'
  std::memset(p, '7', 600);
  b.commit(p + 3);
  EXPECT_EQ(b.view(), "N777");
  b.append("0");
  EXPECT_EQ(b.view(), "N7770");
}

TEST(BlockBuffer, EraseFrontAndClear) {
  BlockBuffer b;
  b.append("N10 %");
  b.erase_front(4);  // a block that gets no number
  EXPECT_EQ(b.view(), "%");
  b.clear();
  EXPECT_EQ(b.view(), "");
  b.append("O1");
  EXPECT_EQ(b.view(), "O1");
}

}  // namespace
}  // namespace clpost
