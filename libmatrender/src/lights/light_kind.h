#pragma once
// What a kind of light a scene describes (a struct of matrender/light.h, an alternative of
// `Light`) brings with it, declared where the light lives as LightKind<ItsDescription>, in the
// manner of pbrt-v4's Create from a parameter dictionary:
//
//   static constexpr const char* kSceneFileType;      its "type" among a scene file's lights
//   static Description read(const matbase::DocumentNode&);     its keys in a scene file, each checked
//                                                     (docs/scene_format.md, "Lights")
//   static void check(const Description&);            what single precision needs of its values
//                                                     to render it, refused with refuse()
//                                                     (light_checks.h)
//   template <class Add>
//   static void prepare(const Description&, Add&& add);   add(the implementation it renders
//                                                     with), one of SceneLight's (scene_light.h)
//
// The scene file's reader, the scene's checks and the light sampler go through these for every
// alternative of `Light`, so none of them names a light.
namespace matrender {

template <class Description>
struct LightKind;

}  // namespace matrender
