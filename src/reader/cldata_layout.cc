#include "reader/cldata_layout.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "reader/cldata_words.h"

namespace clpost::cldata {

namespace {

constexpr Layout kLayouts[] = {
    // APT360 (and the C translation of it): 16-byte header, little-endian, 6 characters of
    // text in an 8-byte word.
    Layout{"APT360"},
    // The same records with big-endian integers and IEEE doubles, as APT processors on
    // big-endian workstations write them.
    Layout{.name = "APT360, big-endian", .little_endian = false},
    // NCL (NCCS NCL/NCLCAM): an 8-byte header of four little-endian int16 — the word count with
    // the header word, type, subtype, ISN —, 8 characters of text in a word, motion records
    // without a surface name, 36-word physical blocks (postworks/pwmacro/clfile.f, nclrd).
    Layout{.name = "NCL",
           .flavor = Flavor::kNcl,
           .field_bytes = 2,
           .number_at = -1,
           .length_at = 0,
           .type_at = 1,
           .subtype_at = 2,
           .isn_at = 3,
           .length_counts_header = true,
           .text_chars = 8,
           .motion_name_words = 0,
           .block_words = 36},
};

// The longest record a CLDATA file can hold: APT360 splits motion into records of 242 words;
// anything far longer is a damaged length, not data.
constexpr int64_t kMaxPlausibleWords = 1 << 16;

uint64_t read_uint(const char* p, size_t n, bool little_endian) {
  uint64_t v = 0;
  for (size_t i = 0; i < n; ++i) {
    const auto b = static_cast<uint64_t>(static_cast<unsigned char>(p[i]));
    v |= little_endian ? b << (8 * i) : b << (8 * (n - 1 - i));
  }
  return v;
}

bool plausible(const RecordHeader& h, int64_t number) {
  return h.number == number && h.length >= 0 && h.length <= kMaxPlausibleWords &&
         is_known_type(h.type);
}

}  // namespace

std::span<const Layout> known_layouts() {
  return kLayouts;
}

RecordHeader read_header(const Layout& layout, const char* p) {
  int64_t f[8] = {};
  for (size_t i = 0; i < layout.fields && i < 8; ++i) {
    const uint64_t u =
        read_uint(p + i * layout.field_bytes, layout.field_bytes, layout.little_endian);
    // Signed: a damaged length reads as negative, not as four billion.
    f[i] = layout.field_bytes == 2 ? int64_t{static_cast<int16_t>(u)}
                                   : int64_t{static_cast<int32_t>(u)};
  }
  return RecordHeader{layout.number_at >= 0 ? f[layout.number_at] : 0,
                      f[layout.length_at] - (layout.length_counts_header ? 1 : 0),
                      f[layout.type_at], f[layout.subtype_at],
                      layout.isn_at >= 0 ? f[layout.isn_at] : 0};
}

uint64_t read_word(const Layout& layout, const char* p) {
  if (layout.word_bytes == 8 &&
      layout.little_endian == (std::endian::native == std::endian::little)) {
    uint64_t v;
    std::memcpy(&v, p, 8);
    return v;
  }
  return read_uint(p, layout.word_bytes, layout.little_endian);
}

double word_double(uint64_t bits) {
  return std::bit_cast<double>(bits);
}

std::optional<int64_t> word_code(const Layout& layout, uint64_t bits) {
  if (layout.flavor == Flavor::kNcl) {
    if ((bits >> 48) == 0 && (bits & 0xFFFF) != 0) return static_cast<int64_t>(bits & 0xFFFF);
    return std::nullopt;
  }
  if (bits != 0 && bits <= 0xFFFFFFFFu) return static_cast<int64_t>(bits);
  return std::nullopt;
}

void append_records(const Layout& layout, std::string& out, std::string_view raw, size_t raw_at) {
  if (layout.block_words == 0) return void(out.append(raw));
  const size_t block = layout.block_bytes(), data = layout.block_data_bytes();
  while (!raw.empty()) {
    const size_t in_block = raw_at % block;
    const size_t n = std::min(raw.size(), block - in_block);
    if (in_block < data) out.append(raw.substr(0, std::min(n, data - in_block)));
    raw.remove_prefix(n);
    raw_at += n;
  }
}

size_t file_offset(const Layout& layout, size_t logical) {
  if (layout.block_words == 0) return logical;
  const size_t data = layout.block_data_bytes();
  return logical / data * layout.block_bytes() + logical % data;
}

const Layout* detect_layout(std::string_view head) {
  for (const Layout& l : kLayouts) {
    const size_t hb = l.header_bytes();
    if (head.size() < hb) continue;
    const RecordHeader first = read_header(l, head.data());
    if (l.flavor == Flavor::kNcl) {
      // The header record fits in the first block, and so does the next record's header.
      if (first.type != kNclHeader || first.length < 15 || first.length > 33) continue;
      const size_t second = hb + static_cast<size_t>(first.length) * l.word_bytes;
      if (head.size() >= second + hb) {
        const RecordHeader next = read_header(l, head.data() + second);
        if (next.length < 0 || !is_known_type(next.type, true)) continue;
      }
      return &l;
    }
    if (!plausible(first, 1)) continue;
    const size_t second = hb + static_cast<size_t>(first.length) * l.word_bytes;
    // The second record's number (its length or type may be damaged: the reader says so).
    if (head.size() >= second + hb && read_header(l, head.data() + second).number != 2) continue;
    return &l;
  }
  return nullptr;
}

}  // namespace clpost::cldata
