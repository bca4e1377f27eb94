#pragma once
// JSON text as a DocumentValue, refused with the problem named: not JSON (with line and column),
// a number beyond a double, a key given twice in one object (JSON allows it, and readers disagree
// on which value wins), nesting deeper than kMaxDocumentDepth.
#include <istream>
#include <string>

#include "matbase/document/document_value.h"

namespace matbase {

// Throws matbase::InputError beginning "<source>: ".
DocumentValue parse_json_document(std::istream& text, const std::string& source);
// The same for a file, which must be a readable regular file.
DocumentValue read_json_document(const std::string& path);

}  // namespace matbase
