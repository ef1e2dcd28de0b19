// The page's only style: black on white, rules and weights rather than colour, A4 or Letter
// (the printer's page; the content fits the narrower A4), a page break before each section.
#include "sheet/sheet_parts.h"

namespace clpost {

std::string sheet_css() {
  return R"(@page { margin: 12mm; }
html { font: 10pt/1.35 "DejaVu Sans", Arial, Helvetica, sans-serif; color: #000; background: #fff; }
body { margin: 0 auto; max-width: 186mm; padding: 6mm; }
h1 { font-size: 17pt; margin: 0 0 3mm; border-bottom: 2pt solid #000; }
h2 { font-size: 13pt; margin: 4mm 0 2mm; border-bottom: 1pt solid #000; }
table { border-collapse: collapse; width: 100%; margin: 0 0 4mm; }
th, td { border: 0.5pt solid #000; padding: 0.8mm 1.2mm; text-align: left; vertical-align: top; }
thead th { background: #e8e8e8; font-weight: bold; }
thead { display: table-header-group; }
td.num { text-align: right; white-space: nowrap; font-variant-numeric: tabular-nums; }
.nw { white-space: nowrap; }
div.side-by-side { display: flex; gap: 4mm; align-items: flex-start; }
div.side-by-side > table { flex: 1 1 auto; width: auto; min-width: 0; }
table.facts { width: auto; min-width: 60%; }
table.facts th { font-weight: bold; white-space: nowrap; }
table.tools, table.holes, table.warnings { font-size: 8.5pt; }
tr, figure { break-inside: avoid; page-break-inside: avoid; }
section.page { break-before: page; page-break-before: always; }
figure { margin: 0 0 4mm; }
figure svg { display: block; width: 100%; height: auto; max-height: 150mm; }
figcaption { font-style: italic; margin-top: 1mm; }
p.total { font-size: 11pt; }
@media print { body { max-width: none; padding: 0; } }
)";
}

}  // namespace clpost
