#pragma once
// Turning a segmentation's pixels into one object: GrabCut and Segment Anything both leave specks
// of background that look like the object and holes where the object looks like its background.
// Masks are width x height, row by row, nonzero inside; regions are 8-connected.
#include <vector>

#include "matbase/image/float_image.h"
#include "matlearn/isolation/prompt.h"

namespace matlearn {

// The largest connected region of `mask` (the first in row order among equals); empty stays empty.
matbase::Mask largest_component(const matbase::Mask& mask, int width, int height);

// The connected regions of `mask` that hold at least one of `points`.
matbase::Mask components_holding(const matbase::Mask& mask, int width, int height, const std::vector<PromptPoint>& points);

// `mask` with its holes filled: every 4-connected region outside it that does not reach the
// image's border becomes inside.
matbase::Mask filled_holes(const matbase::Mask& mask, int width, int height);

// The object: the regions holding the prompt's foreground points, or the largest region when it
// has none (or none of them lands inside), with its holes filled.
matbase::Mask cleaned_object_mask(const matbase::Mask& mask, int width, int height, const Prompt& prompt);

}  // namespace matlearn
