#include "reader/cldata_layout.h"

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
  return RecordHeader{f[layout.number_at], f[layout.length_at], f[layout.type_at],
                      f[layout.subtype_at]};
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

const Layout* detect_layout(std::string_view head) {
  for (const Layout& l : kLayouts) {
    const size_t hb = l.header_bytes();
    if (head.size() < hb) continue;
    const RecordHeader first = read_header(l, head.data());
    if (!plausible(first, 1)) continue;
    const size_t second = hb + static_cast<size_t>(first.length) * l.word_bytes;
    // The second record's number (its length or type may be damaged: the reader says so).
    if (head.size() >= second + hb && read_header(l, head.data() + second).number != 2) continue;
    return &l;
  }
  return nullptr;
}

}  // namespace clpost::cldata
