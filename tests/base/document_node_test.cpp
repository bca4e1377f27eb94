// One reader for JSON and YAML documents: the same values and the same refusals, "<file>: <path>:
// <problem>", whichever syntax the document is written in; the path as a JSON pointer (RFC 6901)
// or dotted keys; typing as JSON has it and as YAML's core schema leaves it to the reader.
#include <cmath>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <yaml-cpp/yaml.h>

#include "matbase/document/document_node.h"
#include "matbase/document/json_document.h"
#include "matbase/document/yaml_document.h"
#include "matbase/input_error.h"

namespace {

using matbase::DocumentNode;
using matbase::DocumentSource;
using matbase::DocumentValue;
using matbase::PathStyle;

DocumentValue json(const std::string& text) {
  std::istringstream in(text);
  return matbase::parse_json_document(in, "s.json");
}

DocumentValue yaml(const std::string& text) { return matbase::yaml_document_value(YAML::Load(text), "c.yaml"); }

// The message a read throws, or "" when it reads.
template <class Read>
std::string refusal(Read read) {
  try {
    read();
  } catch (const matbase::InputError& e) {
    return e.what();
  }
  return "";
}

// The refusal of `read` on the document, read from JSON as a scene file is and from YAML as
// make_dataset's configuration is.
template <class Read>
std::pair<std::string, std::string> refusals(const std::string& json_text, const std::string& yaml_text, Read read) {
  const DocumentValue from_json = json(json_text), from_yaml = yaml(yaml_text);
  const DocumentSource json_source("s.json", PathStyle::JsonPointer), yaml_source("c.yaml", PathStyle::DottedKeys);
  return {refusal([&] { read(DocumentNode(from_json, json_source)); }),
          refusal([&] { read(DocumentNode(from_yaml, yaml_source)); })};
}

}  // namespace

TEST_CASE("JSON and YAML documents are refused in one form: file, path, what was expected and found", "[base]") {
  const auto spp = [](const DocumentNode& root) { root.required("render").required("spp").integer_at_least(1); };
  CHECK(refusals(R"({"render": {"spp": -1}})", "render: {spp: -1}", spp) ==
        std::pair<std::string, std::string>{"s.json: /render/spp: expected a whole number from 1 to 2,147,483,647, got -1",
                                            "c.yaml: render.spp: expected a whole number from 1 to 2,147,483,647, got -1"});
  const auto keys = [](const DocumentNode& root) { root.required("render").expect_keys({"spp", "seed"}); };
  CHECK(refusals(R"({"render": {"sp": 4}})", "render: {sp: 4}", keys) ==
        std::pair<std::string, std::string>{R"(s.json: /render/sp: unknown key (allowed here: "spp", "seed"))",
                                            R"(c.yaml: render.sp: unknown key (allowed here: "spp", "seed"))"});
  const auto missing = [](const DocumentNode& root) { root.required("camera"); };
  CHECK(refusals("{}", "{}", missing) ==
        std::pair<std::string, std::string>{R"(s.json: missing key "camera")", R"(c.yaml: missing key "camera")"});
  const auto empty = [](const DocumentNode& root) { root.find("seed"); };
  CHECK(refusals(R"({"seed": null})", "seed:", empty).second ==
        "c.yaml: seed: no value given: write one, or leave the key out for its default");
  CHECK(refusals(R"({"seed": null})", "seed: ~", empty).first ==
        "s.json: /seed: no value given: write one, or leave the key out for its default");
  const auto mode = [](const DocumentNode& root) { root.required("mode").choice({"fit", "fixed"}); };
  CHECK(refusals(R"({"mode": "fill"})", "mode: fill", mode) ==
        std::pair<std::string, std::string>{R"(s.json: /mode: expected one of "fit", "fixed", got "fill")",
                                            R"(c.yaml: mode: expected one of "fit", "fixed", got fill)"});
  const auto rgb = [](const DocumentNode& root) { root.required("color").items(3, "[r, g, b]"); };
  CHECK(refusals(R"({"color": {"r": 1}})", "color: [1, 2]", rgb) ==
        std::pair<std::string, std::string>{"s.json: /color: expected [r, g, b], got a mapping of keys",
                                            "c.yaml: color: expected [r, g, b], got a list"});
}

TEST_CASE("Numbers are read from their spelling, ranges stated in words", "[base]") {
  const DocumentSource source("s.json", PathStyle::JsonPointer);
  const DocumentValue doc = json(R"({"a": 0.1, "b": 3.0, "c": 1e3, "d": 3.5, "e": "64", "f": 18446744073709551615,
                                    "g": -0.0, "h": 2e-310})");
  const DocumentNode root(doc, source);
  CHECK(root.required("a").number() == 0.1);  // correctly rounded, as strtod reads it
  CHECK(root.required("b").integer_in(0, 10) == 3);  // 3 and 3.0 are one number to JSON's writers
  CHECK(root.required("c").whole_number(0, 5000) == 1000);
  CHECK(refusal([&] { root.required("d").integer_in(0, 10); }) == "s.json: /d: expected a whole number from 0 to 10, got 3.5");
  CHECK(refusal([&] { root.required("e").number(); }) == "s.json: /e: expected a number, got \"64\"");
  CHECK(root.required("f").seed() == 18446744073709551615ull);  // all 64 bits, not through a double
  CHECK(std::signbit(root.required("g").number()));
  CHECK(root.required("h").positive() == 2e-310);  // subnormal, yet a number
  CHECK(refusal([&] { root.required("a").number_in(0.5, 1.0); }) == "s.json: /a: expected a number from 0.5 to 1, got 0.1");
  CHECK(refusal([&] { root.required("g").positive(); }) == "s.json: /g: expected a number greater than 0, got -0.0");
  CHECK(refusal([&] { root.required("d").number_in(-1.0, 1.0, true); }) ==
        "s.json: /d: expected a number greater than -1 and at most 1, got 3.5");
  CHECK(refusal([&] { root.required("e").non_negative(); }) == "s.json: /e: expected a number of at least 0, got \"64\"");
}

TEST_CASE("YAML's quoted scalars are text; unquoted ones are what the reader reads", "[base]") {
  const DocumentSource source("c.yaml", PathStyle::DottedKeys);
  const DocumentValue doc = yaml("samples: 64\nquoted: \"64\"\nname: 2024\nflag: true\nword: True\ntagged: !!str 5\n");
  const DocumentNode root(doc, source);
  CHECK(root.required("samples").integer_at_least(1) == 64);
  CHECK(root.required("samples").text() == "64");
  CHECK(refusal([&] { root.required("quoted").integer_at_least(1); }) ==
        "c.yaml: quoted: expected a whole number from 1 to 2,147,483,647, got \"64\"");
  CHECK(root.required("name").text() == "2024");
  CHECK(root.required("flag").boolean());
  CHECK(refusal([&] { root.required("word").boolean(); }) == "c.yaml: word: expected true or false, got True");
  CHECK(refusal([&] { root.required("tagged").number(); }) == "c.yaml: tagged: expected a number, got \"5\"");
  // JSON's strings are text and its numbers numbers: no number reads as text.
  const DocumentSource json_source("s.json", PathStyle::JsonPointer);
  const DocumentValue json_doc = json(R"({"name": 2024, "flag": "true"})");
  const DocumentNode json_root(json_doc, json_source);
  CHECK(refusal([&] { json_root.required("name").text(); }) == "s.json: /name: expected a string, got 2024");
  CHECK(refusal([&] { json_root.required("flag").boolean(); }) == "s.json: /flag: expected true or false, got \"true\"");
}

TEST_CASE("Paths name keys as RFC 6901 or as dotted keys, and options that set them", "[base]") {
  // RFC 6901, section 3: "~" is "~0" and "/" is "~1" within a token.
  const DocumentSource pointer("s.json", PathStyle::JsonPointer);
  const DocumentValue doc = json(R"({"a/b": {"m~n": [0, {"x": true}]}})");
  const DocumentNode root(doc, pointer);
  const DocumentNode x = root.required("a/b").required("m~n").items()[1].required("x");
  CHECK(x.place() == "s.json: /a~1b/m~0n/1/x");
  DocumentSource dotted("c.yaml", PathStyle::DottedKeys);
  dotted.overridden("render.samples", "--spp");
  dotted.overridden("render.resolution.1", "--set render.resolution.1");
  CHECK(dotted.place("render.samples") == "--spp (render.samples)");
  CHECK(dotted.place("render.resolution") == "--set render.resolution.1 (render.resolution)");
  CHECK(dotted.place("render.seed") == "c.yaml: render.seed");
  CHECK(dotted.place("") == "c.yaml");
}

TEST_CASE("Documents that say a key twice, nest without end or hold no double are refused", "[base]") {
  CHECK(refusal([] { json(R"({"lights": [{"power": 1, "power": 2}]})"); }) ==
        "s.json: /lights/0/power: given twice; say it once");
  CHECK(refusal([] { yaml("render:\n  samples: 1\n  samples: 2\n"); }) ==
        "c.yaml: render.samples: given twice (lines 2 and 3); say it once");
  CHECK(refusal([] { yaml(R"({"seed": 1, "seed": 2})"); }) ==
        "c.yaml: seed: given twice (line 1, columns 2 and 13); say it once");
  CHECK(refusal([] { json(std::string(300, '[') + std::string(300, ']')); }) ==
        "s.json: lists and mappings nest deeper than 256 levels");
  CHECK(refusal([] { yaml("a: &x [*x]\n"); }).find("nest deeper than 256 levels") != std::string::npos);
  CHECK(refusal([] { json(R"({"a": 1e309})"); }) == "s.json: /a: the number '1e309' is too large for a double");
  CHECK(refusal([] { json(R"({"render": {"seed": 1e309}})"); }) == "s.json: /render/seed: the number '1e309' is too large for a double");
  CHECK(refusal([] { json(R"({"a": [1, 2, -1e400]})"); }) == "s.json: /a/2: the number '-1e400' is too large for a double");
  CHECK(refusal([] { json(R"({"a": 1,})"); }).rfind("s.json: not valid JSON: parse error at line 1, column 9", 0) == 0);
  CHECK(refusal([] { yaml("? [a, b]\n: 1\n"); }) == "c.yaml: a key must be a single value, not a list or a mapping");
}
