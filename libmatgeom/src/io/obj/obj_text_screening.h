#pragma once
// OBJ text as tinyobjloader sees it: screened before tinyobjloader 2.0.0rc10 parses it, for the
// inputs it handles badly and for the values it would otherwise fill in or wrap unseen.
#include <cstddef>
#include <string>
#include <string_view>

namespace matgeom::obj {

// Checks every vertex and face statement of OBJ text where it is written, throwing
// std::runtime_error("<path>: line <n>: <problem>"): vertex coordinates are finite numbers of
// the count the statement takes; faces have 3 or more corners (up to kMaxPolygonCorners), and
// lines and points 1 or more, whose indices name vertices that come before them, reported as
// written. Prepares the text for tinyobjloader, which mishandles two statements that mean nothing
// to a triangle mesh: it copies every "t" (subdivision tag) line, with up to 3 x 8192 values
// each, into every shape, so a few kilobytes of tags can claim gigabytes; and it converts "vw"
// (skin weight) joint numbers to int unchecked, undefined for 1e40. Their lines are blanked, as
// are comments after corners (which tinyobjloader would read as index 0); line numbers stay. A
// line ending in a backslash goes on in the next, as Blender reads it; the lines are joined.
void screen_obj_text(const std::string& path, std::string& text);

// The number of the first line of OBJ text whose "usemtl" names `material` (the whole rest of
// the line, trimmed, as Blender reads it); 0 if none does.
size_t first_use_line(const std::string& text, std::string_view material);

// Screened OBJ text as tinyobjloader must read it to see what Blender 3.4 sees: "usemtl" names
// and "mtllib" file names (the whole rest of the line) as one word (material_names.h); "s" as "s 1" or "s 0" by Blender's rule (any integer but 0 is
// smooth; tinyobjloader would read "s -1" as off); and "s 0" after every "o", since Blender starts
// each object flat. Lines end in \n; the "o" lines' extra statements shift later line numbers,
// so messages take theirs from the screened text.
std::string tinyobj_text(const std::string& screened);

// Whether the OBJ text has an "mtllib" statement.
bool names_material_library(const std::string& text);

}  // namespace matgeom::obj
