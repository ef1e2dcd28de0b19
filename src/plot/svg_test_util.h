#pragma once
// Test helper for the plot tests: a small XML well-formedness checker that also lists the
// elements, so tests can count them and read their attributes and text.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace clpost::testing {

struct XmlElement {
  std::string tag;
  std::map<std::string, std::string> attrs;  // values with entities decoded
  std::string text;                          // the element's own text, entities decoded
  std::string attr(const std::string& name) const {
    auto it = attrs.find(name);
    return it == attrs.end() ? std::string() : it->second;
  }
};

struct XmlDoc {
  bool ok = false;
  std::string error;                 // what was wrong and where (byte offset)
  std::vector<XmlElement> elements;  // in document order
  // Elements with this tag (any when empty) whose class attribute is `cls`.
  std::vector<const XmlElement*> with_class(std::string_view cls, std::string_view tag = {}) const {
    std::vector<const XmlElement*> out;
    for (const XmlElement& e : elements)
      if (e.attr("class") == cls && (tag.empty() || e.tag == tag)) out.push_back(&e);
    return out;
  }
  std::vector<const XmlElement*> with_tag(std::string_view tag) const {
    std::vector<const XmlElement*> out;
    for (const XmlElement& e : elements)
      if (e.tag == tag) out.push_back(&e);
    return out;
  }
};

// Decodes the entity at s[i] ('&'), appending it to `out`; returns its length or 0 when it is not
// one of &amp; &lt; &gt; &quot; &apos; &#N; &#xN;.
inline size_t xml_entity(std::string_view s, size_t i, std::string& out) {
  const size_t semi = s.find(';', i);
  if (semi == std::string_view::npos || semi - i > 10) return 0;
  const std::string_view name = s.substr(i + 1, semi - i - 1);
  static const std::map<std::string_view, char> kNamed = {
      {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
  if (auto it = kNamed.find(name); it != kNamed.end()) {
    out += it->second;
    return semi - i + 1;
  }
  if (name.size() >= 2 && name[0] == '#') {
    const bool hex = name[1] == 'x';
    const std::string digits(name.substr(hex ? 2 : 1));
    if (digits.empty()) return 0;
    for (char c : digits)
      if (!(hex ? std::isxdigit(static_cast<unsigned char>(c))
                : std::isdigit(static_cast<unsigned char>(c))))
        return 0;
    out += '?';  // the tests never need the character itself
    return semi - i + 1;
  }
  return 0;
}

inline bool xml_name_char(char c, bool first) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalpha(u) || c == '_' || c == ':' ||
         (!first && (std::isdigit(u) || c == '-' || c == '.'));
}

// Checks: an optional XML declaration, then exactly one root element; tags balance; names are
// XML names; attribute values are double-quoted, hold no '<', no duplicate names, and every '&'
// (in values and text) starts a valid entity; no text outside the root; comments closed.
inline XmlDoc check_xml(std::string_view s) {
  XmlDoc doc;
  std::vector<size_t> stack;  // indices into doc.elements
  size_t roots = 0;
  auto fail = [&](std::string what, size_t at) {
    doc.ok = false;
    doc.error = what + " at byte " + std::to_string(at);
    return doc;
  };
  size_t i = 0;
  if (s.substr(0, 5) == "<?xml") {
    const size_t e = s.find("?>");
    if (e == std::string_view::npos) return fail("unterminated XML declaration", 0);
    i = e + 2;
  }
  while (i < s.size()) {
    const char c = s[i];
    if (c != '<') {
      if (stack.empty()) {
        if (!std::isspace(static_cast<unsigned char>(c))) return fail("text outside the root", i);
        ++i;
        continue;
      }
      std::string& text = doc.elements[stack.back()].text;
      if (c == '&') {
        const size_t n = xml_entity(s, i, text);
        if (n == 0) return fail("raw '&' in text", i);
        i += n;
        continue;
      }
      text += c;
      ++i;
      continue;
    }
    if (s.substr(i, 4) == "<!--") {
      const size_t e = s.find("-->", i + 4);
      if (e == std::string_view::npos) return fail("unterminated comment", i);
      i = e + 3;
      continue;
    }
    if (s.substr(i, 2) == "</") {
      size_t j = i + 2;
      while (j < s.size() && xml_name_char(s[j], j == i + 2)) ++j;
      const std::string name(s.substr(i + 2, j - i - 2));
      while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
      if (j >= s.size() || s[j] != '>') return fail("bad end tag", i);
      if (stack.empty() || doc.elements[stack.back()].tag != name)
        return fail("end tag </" + name + "> does not match", i);
      stack.pop_back();
      i = j + 1;
      continue;
    }
    // A start tag.
    size_t j = i + 1;
    if (j >= s.size() || !xml_name_char(s[j], true)) return fail("'<' that starts no tag", i);
    while (j < s.size() && xml_name_char(s[j], false)) ++j;
    XmlElement e;
    e.tag = std::string(s.substr(i + 1, j - i - 1));
    bool self_closing = false;
    for (;;) {
      const size_t before = j;
      while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
      if (j >= s.size()) return fail("unterminated tag <" + e.tag, i);
      if (s[j] == '>') {
        ++j;
        break;
      }
      if (s.substr(j, 2) == "/>") {
        self_closing = true;
        j += 2;
        break;
      }
      if (j == before) return fail("no space before an attribute", j);
      const size_t n0 = j;
      if (!xml_name_char(s[j], true)) return fail("bad attribute name", j);
      while (j < s.size() && xml_name_char(s[j], false)) ++j;
      const std::string name(s.substr(n0, j - n0));
      if (j >= s.size() || s[j] != '=') return fail("attribute " + name + " without '='", j);
      ++j;
      if (j >= s.size() || s[j] != '"') return fail("attribute " + name + " not double-quoted", j);
      ++j;
      std::string value;
      while (j < s.size() && s[j] != '"') {
        if (s[j] == '<') return fail("'<' in attribute " + name, j);
        if (s[j] == '&') {
          const size_t n = xml_entity(s, j, value);
          if (n == 0) return fail("raw '&' in attribute " + name, j);
          j += n;
          continue;
        }
        value += s[j++];
      }
      if (j >= s.size()) return fail("unterminated attribute " + name, n0);
      ++j;
      if (!e.attrs.emplace(name, value).second) return fail("duplicate attribute " + name, n0);
    }
    if (stack.empty() && ++roots > 1) return fail("second root element", i);
    doc.elements.push_back(std::move(e));
    if (!self_closing) stack.push_back(doc.elements.size() - 1);
    i = j;
  }
  if (!stack.empty()) return fail("unclosed <" + doc.elements[stack.back()].tag + ">", s.size());
  if (roots != 1) return fail("no root element", 0);
  doc.ok = true;
  return doc;
}

// The numbers in SVG path data or a list, in order ("M1 2 L3 4" -> 1 2 3 4).
inline std::vector<double> numbers_in(std::string_view d) {
  std::vector<double> out;
  const std::string s(d);
  const char* p = s.c_str();
  while (*p != '\0') {
    if (std::isdigit(static_cast<unsigned char>(*p)) || *p == '-' || *p == '.') {
      char* end = nullptr;
      out.push_back(std::strtod(p, &end));
      p = end;
    } else {
      ++p;
    }
  }
  return out;
}

// How often `needle` occurs in `hay`.
inline size_t count_of(std::string_view hay, std::string_view needle) {
  size_t n = 0;
  for (size_t i = hay.find(needle); i != std::string_view::npos; i = hay.find(needle, i + 1)) ++n;
  return n;
}

// check_xml() with the expectations every picture meets: well-formed, one <svg> root.
inline XmlDoc parsed(const std::string& svg) {
  XmlDoc d = check_xml(svg);
  EXPECT_TRUE(d.ok) << d.error;
  if (d.ok) {
    EXPECT_EQ(d.elements.front().tag, "svg");
  }
  return d;
}

}  // namespace clpost::testing
