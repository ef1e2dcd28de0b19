#pragma once
// A program's whole motion drawn in the XZ plane (a backplot), as the control would move the
// tool: rapids dashed, feeds solid, arcs as arcs, synchronized thread cuts bold.
#include <string>
#include <string_view>
#include <vector>

#include "plot/mill_views.h"
#include "plot/move_geometry.h"
#include "plot/path_thinner.h"
#include "simulator/toolpath.h"

namespace clpost {

// A standalone SVG document 1200 px wide:
//  - Z horizontal (+Z to the right), X (the radius) upward, one scale for both, fitted to the
//    moves (arcs included) with a margin; the spindle axis (X 0) is shown when the part is
//    closer to it than it is tall;
//  - a grid with numbered ticks (1, 2, 5 x 10^k) and axis titles in the toolpath's units;
//  - consecutive moves of one kind merged into one <path> (subpaths where they do not join):
//    class="rapid" (thin, dashed, grey), "feed" (solid, blue), "arc" (kArcCw / kArcCcw as SVG
//    arcs, clockwise = G2 with Z right and X up; teal), "thread" (kThread; bold, orange), so a
//    100k-move program stays a few thousand elements; moves with non-finite coordinates are
//    skipped;
//  - a circle where the motion starts, a legend and a line of move counts and path lengths;
//  - under the moves, each section's run-in and run-out (ThreadSection::zones, when known) as a
//    band hatched in grey across what its passes span, so that where the lead is not yet right
//    shows without colour; the legend names the hatch;
//  - `title` (escaped) at the top; empty: "Backplot";
//  - when `sections` is given and not empty, each thread's section picture
//    (thread_section_svg.h) under the plot, scaled to the width;
//  - when `mill` has C-axis work (plot/mill_views.h), under the plot and above the sections:
//    the face view (the part face seen along -Z at C0, with the stock circle, C0 and C90 marked,
//    face holes as marks) and the unrolled peripheral view (Z across, the arc length up, lines
//    at C0, C90, ..., radial holes as marks), each only when there is such work; without it the
//    document is the lathe's side view alone, as it always was.
// The side view is the lathe's: the caller leaves a live tool's C-axis work out of it
// (MillViews::side_move), which the face and peripheral views draw; `note` says so.
// An empty toolpath gives a valid document with an empty grid and the words "no moves".
std::string backplot_svg(const Toolpath& toolpath,
                         const std::vector<ThreadSection>* sections = nullptr,
                         std::string_view title = {}, const MillViewsDrawn* mill = nullptr,
                         std::string_view note = {});

// The same picture of a thinned path (path_thinner.h): its moves drawn, the line of move counts
// and lengths and the frame from what every move of the program measures; `note`, when not
// empty, in italics on a line of its own under the legend (the plot moves down by that line).
std::string backplot_svg(const ThinnedPath& path, const std::vector<ThreadSection>* sections,
                         std::string_view title, std::string_view note,
                         const MillViewsDrawn* mill = nullptr);

// The side view's note on the `milling` moves left to the C-axis views ("" for none).
std::string milling_note(size_t milling);

// The scale (px per program unit) backplot_svg draws at, for a program whose moves cover `all`
// and whose cutting moves cover `cut`. It only shrinks as the boxes grow.
double backplot_scale(const Bounds& all, const Bounds& cut);

}  // namespace clpost
