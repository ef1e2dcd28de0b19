#pragma once
// The sections of the sheet's page, each in its own file (sheet_html.cc puts them together).
#include <string>

#include "sheet/sheet.h"

namespace clpost {

std::string sheet_css();                           // sheet_style.cc
std::string tools_section(const SheetData& d);     // sheet_tools.cc
std::string threads_sections(const SheetData& d);  // sheet_threads.cc: one section per thread
std::string holes_section(const SheetData& d);     // sheet_holes.cc
std::string warnings_section(const SheetData& d);  // sheet_warnings.cc

}  // namespace clpost
