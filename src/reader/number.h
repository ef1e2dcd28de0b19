#pragma once
// APT numbers: `1.`, `.5`, `-0.5`, `+2`, `1E3`, `1.5e-3`. Strict grammar first (so `1.2.3`, `--1`,
// `1e`, `-inf` are rejected), then std::from_chars for the value.
#include <string_view>

namespace clpost::reader {

enum class NumberStatus { kOk, kInvalid, kOutOfRange };

// [+-]? (digits [. digits*] | . digits) ([eE] [+-]? digits)?  — the whole of `text`.
NumberStatus parse_number(std::string_view text, double& value);

// True when every character could belong to a number ([0-9.eE+-]): such a token is a number or
// an invalid one, never a word.
bool looks_numeric(std::string_view text);

}  // namespace clpost::reader
