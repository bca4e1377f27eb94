#pragma once
// MTL text as tinyobjloader sees it: every number checked where it is written, and markers for
// the values a material leaves out.
#include <string>
#include <vector>

namespace matgeom::obj {

// Checks every statement of the .mtl text `mtl_path` holds, throwing std::runtime_error
// ("<obj_path>: <mtl_path>: line <n>: <statement>: <problem>") for a number that is not one or
// lies outside the range its parameter can use (each range is the parameter table's), a
// statement with the wrong count of numbers, a map option with a value it cannot take, a map
// without a file name, a material without a name. A material defined twice keeps its first
// definition, as in Blender, and `notes` says so. Returns the text with every
// statement as tinyobjloader 2.0.0rc10 must read it: a colour given as one number written as
// three (the MTL rule; tinyobjloader would fill 0), and -o, -s and -t given fewer than three
// numbers padded with their defaults (tinyobjloader would read the file name as the third).
std::string screened_mtl_text(const std::string& obj_path, const std::string& mtl_path, const std::string& text,
                              std::vector<std::string>& notes);

// An .mtl text with kNotGivenMarkers at the start and after every "newmtl" line, recognised as
// tinyobjloader's LoadMtl recognises it (trailing blanks trimmed, then "newmtl" and a blank).
// Lines end in \n after this.
std::string with_not_given_markers(const std::string& text);

}  // namespace matgeom::obj
