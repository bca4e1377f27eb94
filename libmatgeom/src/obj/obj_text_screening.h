#pragma once
// Text as tinyobjloader sees it: the OBJ and MTL text is screened and marked before
// tinyobjloader 2.0.0rc10 parses it, for the inputs it handles badly and for the values it
// would otherwise fill in unseen.
#include <string>

namespace matgeom::obj {

// Prepares OBJ text for tinyobjloader 2.0.0rc10, which mishandles two statements that mean
// nothing to a triangle mesh: it copies every "t" (subdivision tag) line, with up to 3 x 8192
// values each, into every shape, so a few kilobytes of tags can claim gigabytes; and it converts
// "vw" (skin weight) joint numbers to int unchecked, undefined for 1e40. Their lines are blanked,
// which keeps the line numbers of tinyobjloader's messages. Polygons with too many corners are
// refused.
void screen_obj_text(const std::string& path, std::string& text);

// An .mtl text with kNotGivenMarkers at the start and after every "newmtl" line, recognised as
// tinyobjloader's LoadMtl recognises it (trailing blanks trimmed, then "newmtl" and a blank).
// Lines end in \n after this.
std::string with_not_given_markers(const std::string& text);

}  // namespace matgeom::obj
