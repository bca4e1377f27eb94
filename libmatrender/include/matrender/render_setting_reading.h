#pragma once
// Reading declared render settings (matrender/render_setting_declarations.h) from a document:
// the scene file's "render" block, make_dataset's configuration. A refusal names the document,
// the key and the declaration's expectation.
#include "matbase/document/document_node.h"
#include "matrender/render_setting_declarations.h"

namespace matrender {

// Reads `value` as `setting` says a value must be and sets it in `settings`.
void read_render_setting(const matbase::DocumentNode& value, const RenderSettingDeclaration& setting,
                         RenderSettings& settings);

}  // namespace matrender
