// Compiled by the TemplateFieldTypo tests (tests/CMakeLists.txt): with FIELD a name template
// fanuc_g76 declares it compiles; with a name it does not ("leed"), it must not.
#include "controls/fanuc/fanuc_templates.h"
#include "machine/template_values.h"

namespace clpost {

void fill() {
  TemplateFill<tmpl::kFanucG76> a;
  a.text<FIELD>("1.5");
}

}  // namespace clpost
