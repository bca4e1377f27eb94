#pragma once
// The generators behind make_builtin_object, one per category. Each returns an object resting
// on z = 0, centred on the z axis, in metres, shape and materials varied by the seed.
#include <cstdint>

#include "matgeom/object_asset.h"

namespace matgeom::builtin {

// tables.cpp, seating.cpp, storage.cpp, beds.cpp (built from joinery.h and furniture_solids.h)
ObjectAsset make_table(uint32_t seed);
ObjectAsset make_desk(uint32_t seed);
ObjectAsset make_chair(uint32_t seed);
ObjectAsset make_stool(uint32_t seed);
ObjectAsset make_sofa(uint32_t seed);
ObjectAsset make_cabinet(uint32_t seed);
ObjectAsset make_shelf(uint32_t seed);
ObjectAsset make_bed(uint32_t seed);

// tableware.cpp
ObjectAsset make_mug(uint32_t seed);
ObjectAsset make_bowl(uint32_t seed);
ObjectAsset make_bottle(uint32_t seed);
ObjectAsset make_plant_pot(uint32_t seed);
ObjectAsset make_basket(uint32_t seed);

// vase.cpp
ObjectAsset make_vase(uint32_t seed);

// decor.cpp
ObjectAsset make_pillow(uint32_t seed);
ObjectAsset make_lamp(uint32_t seed);
ObjectAsset make_book(uint32_t seed);
ObjectAsset make_picture_frame(uint32_t seed);

}  // namespace matgeom::builtin
