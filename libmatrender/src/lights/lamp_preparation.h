#pragma once
// How a described lamp (a struct of matrender/lamp.h, an alternative of `Lamp`) becomes the
// lights it renders with, declared where those lights live as LampPreparation<ItsDescription>:
//
//   static void check(const Description&);            what single precision needs of its values
//                                                     to render it, refused with refuse()
//                                                     (light_checks.h)
//   template <class Add>
//   static void prepare(const Description&, Add&& add);   add(the light it renders with), one
//                                                     of `Light`'s alternatives (lights/light.h)
//
// The scene's checks and the light sampler go through these for every alternative of `Lamp`, so
// neither names a lamp. Reading a lamp from a scene file is the scene description's
// (scene_description/lamp_reading.h): the lights know nothing of files.
namespace matrender {

template <class Description>
struct LampPreparation;

}  // namespace matrender
