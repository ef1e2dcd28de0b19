#pragma once
// The physical layout of a binary CLDATA file: how a record's header and words are stored.
// Producers differ (APT360: four little-endian 32-bit header integers and 8-byte words; others
// use 16-bit headers or big-endian data), so a layout is a small description, and the reader is
// the same for all of them. detect_layout() finds the layout from the file's first bytes.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace clpost::cldata {

struct Layout {
  std::string_view name;      // "APT360"
  uint8_t field_bytes = 4;    // bytes per header integer: 2 or 4
  uint8_t fields = 4;         // header integers
  bool little_endian = true;  // header integers and words
  // Which header integer holds what (0-based).
  uint8_t number_at = 0;   // record number, 1, 2, ...
  uint8_t length_at = 1;   // words after the header
  uint8_t type_at = 2;     // 1000, 2000, ... 14000
  uint8_t subtype_at = 3;  // major word code, motion kind, ...
  uint8_t word_bytes = 8;  // a double, a minor word code (an integer), or text
  uint8_t text_chars = 6;  // characters of text in a word; the rest is blank padding

  size_t header_bytes() const { return size_t{field_bytes} * fields; }
};

struct RecordHeader {
  int64_t number = 0;
  int64_t length = 0;  // in words
  int64_t type = 0;
  int64_t subtype = 0;
};

// The layouts clpost knows, APT360's first.
std::span<const Layout> known_layouts();
// The layout of a binary CLDATA file from its first bytes (as many as are at hand, at least a
// header), or nullptr when they are not one: the first record must be record 1 of a known type
// with a possible length, and the second one, when its header is at hand, numbered 2.
const Layout* detect_layout(std::string_view head);

RecordHeader read_header(const Layout& layout, const char* p);
// A word as an unsigned integer in the layout's byte order, and as a double.
uint64_t read_word(const Layout& layout, const char* p);
double word_double(uint64_t bits);

}  // namespace clpost::cldata
