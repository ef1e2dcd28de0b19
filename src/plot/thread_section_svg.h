#pragma once
// A thread's cross-section as a picture: the finished profile cut into the part and the tool's V
// at every pass, so a machinist sees at a glance how deep each pass goes and how the tool walks
// down the flank.
#include <string>
#include <string_view>

#include "plot/svg_writer.h"
#include "simulator/toolpath.h"

namespace clpost {

// A standalone SVG document (about 1100 px wide) of the section:
//  - the part as cut: the envelope of every pass's V (depth d_i at shift sigma_i, included angle
//    tool_angle), hatched, over one groove per start plus half a pitch either side; external
//    threads have the part below the thread surface, internal ones above it (the picture is
//    always drawn with the radius growing upward and the cutting direction to the right);
//  - a dashed line at the full depth D, and a depth ruler with the pass depths;
//  - each pass's V as an outline `<g class="pass" data-pass="n" data-start="k" data-kind="...">`
//    with a tooltip, coloured by kind (rough blue, finish red, spring green, drawn wide and
//    pale under the finish pass it repeats); starts differ by dash pattern and tip marker and
//    sit side by side, start k one pitch after start k-1 (schematic: the picture does not show
//    which way the helix runs);
//  - the pass numbers next to the tips (passes sharing a tip share a label, "6,7"), and a side
//    table "pass start depth step shift kind" in cutting order (3 decimals in mm, 4 in inch);
//  - the title and a line of thread data, a legend, and a scale bar in mm or in;
//  - when the run-in and run-out are known (ThreadSection::zones), a strip at the bottom: the
//    synchronized cut as a bar from its start (left) to its end, the run-in and the run-out
//    hatched in grey at its ends (the whole bar when no length has the right lead), with the
//    lead-axis coordinates and a line giving both lengths, the speed and where the lead is right.
// Passes with non-finite numbers are listed but not drawn; an empty section gives a valid
// picture of the nominal V of depth D.
std::string thread_section_svg(const ThreadSection& section);

// The same picture drawn into another document (e.g. as an inset): thread_section_size() is the
// size it needs, draw_thread_section() draws it with its top-left corner at the current origin.
// `id_prefix` makes the ids of its clip path and hatch pattern unique within the document.
SvgSize thread_section_size(const ThreadSection& section);
void draw_thread_section(SvgWriter& w, const ThreadSection& section, std::string_view id_prefix);

}  // namespace clpost
