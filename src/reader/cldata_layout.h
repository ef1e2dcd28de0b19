#pragma once
// The physical layout of a binary CLDATA file: how a record's header and words are stored.
// Producers differ (APT360: four little-endian 32-bit header integers and 8-byte words; NCL:
// four 16-bit header integers, the header word counted in the length, records run through
// physical blocks of 36 words whose last is not used), so a layout is a small description, and
// the reader is the same for all of them. detect_layout() finds the layout from the file's
// first bytes.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace clpost::cldata {

// Whose records: the same record types mean slightly different things (cldata_reader.h).
enum class Flavor : uint8_t { kApt360, kNcl };

struct Layout {
  std::string_view name;  // "APT360"
  Flavor flavor = Flavor::kApt360;
  uint8_t field_bytes = 4;    // bytes per header integer: 2 or 4
  uint8_t fields = 4;         // header integers
  bool little_endian = true;  // header integers and words
  // Which header integer holds what (0-based); number_at -1: records are not numbered.
  int8_t number_at = 0;    // record number, 1, 2, ...
  uint8_t length_at = 1;   // words after the header (with length_counts_header: and the header)
  uint8_t type_at = 2;     // 1000, 2000, ... 14000
  uint8_t subtype_at = 3;  // major word code, motion kind, ...
  int8_t isn_at = -1;      // the part program's statement number, when the header has it
  bool length_counts_header = false;
  uint8_t word_bytes = 8;         // a double, a minor word code (an integer), or text
  uint8_t text_chars = 6;         // characters of text in a word; the rest is blank padding
  uint8_t motion_name_words = 2;  // words before a motion record's points (the surface name)
  // Physical blocks of this many words, the last of each not used (a record goes on in the
  // next block); 0: none.
  uint16_t block_words = 0;

  size_t header_bytes() const { return size_t{field_bytes} * fields; }
  size_t block_bytes() const { return size_t{block_words} * word_bytes; }
  // Bytes of records in a block.
  size_t block_data_bytes() const { return block_bytes() - word_bytes; }
};

struct RecordHeader {
  int64_t number = 0;  // 0 when the layout does not number records
  int64_t length = 0;  // in words, after the header
  int64_t type = 0;
  int64_t subtype = 0;
  int64_t isn = 0;
};

// The layouts clpost knows, APT360's first.
std::span<const Layout> known_layouts();
// The layout of a binary CLDATA file from its first bytes (as many as are at hand, at least a
// header), or nullptr when they are not one. APT360's layouts: the first record must be record
// 1 of a known type with a possible length, and the second one, when its header is at hand,
// numbered 2. NCL's: the first record is its clfile header (type 7400, at least 15 words), the
// second one of a known type.
const Layout* detect_layout(std::string_view head);

RecordHeader read_header(const Layout& layout, const char* p);
// A word as an unsigned integer in the layout's byte order, and as a double.
uint64_t read_word(const Layout& layout, const char* p);
double word_double(uint64_t bits);
// The minor word code a word holds, if it holds one (as a double it would be a denormal, which
// no CAM system writes as a coordinate). APT360: any integer below 2^32; NCL: the low 16 bits,
// the top 16 zero.
std::optional<int64_t> word_code(const Layout& layout, uint64_t bits);

// Blocked layouts: the bytes of the record stream (the blocks' unused words left out) of `raw`,
// the file's bytes from offset `raw_at` on, appended to `out`; and the file offset of byte
// `logical` of the record stream. Unblocked layouts: `raw` as it is, and `logical`.
void append_records(const Layout& layout, std::string& out, std::string_view raw, size_t raw_at);
size_t file_offset(const Layout& layout, size_t logical);

}  // namespace clpost::cldata
