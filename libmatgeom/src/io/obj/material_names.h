#pragma once
// Material names as Blender reads them, carried through tinyobjloader 2.0.0rc10. Blender takes the
// whole rest of a "newmtl" or "usemtl" line, trimmed, as the name ("newmtl Hard Shiny Plastic"),
// and 3ds Max and SketchUp write such names; tinyobjloader reads one word for "usemtl". The
// texts handed to tinyobjloader therefore spell each name as one word, its blanks and '%'
// percent-encoded, and every name that comes back is decoded.
#include <string>
#include <string_view>

namespace matgeom::obj {

// The name a "newmtl" or "usemtl" line gives: what follows the keyword, without the blanks
// (and line ends) around it.
std::string_view statement_name(std::string_view line);

// `name` as one word: ' ' as %20, '\t' as %09, '%' as %25; a name without them is unchanged.
std::string name_word(std::string_view name);

// The name a word of name_word spells.
std::string word_name(std::string_view word);

}  // namespace matgeom::obj
