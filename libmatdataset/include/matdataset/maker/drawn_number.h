#pragma once
// A quantity make_dataset draws for each frame or variant (a lamp's power, a distractor's count):
// one value or a range, how the configuration spells it, and the draw.
#include "matbase/document/document_node.h"
#include "matdataset/maker/seed_stream.h"

namespace matdataset {

// One value (low == high), or uniform on [low, high], or uniform in its logarithm there (powers,
// strengths, illuminances: each factor of ten gets an equal share).
struct DrawnNumber {
  double low = 0.0;
  double high = 0.0;
  bool logarithmic = false;
  static DrawnNumber value(double v, bool logarithmic = false) { return {v, v, logarithmic}; }
  bool operator==(const DrawnNumber& other) const {
    return low == other.low && high == other.high && logarithmic == other.logarithmic;
  }
};

// A value, or [min, max] with min <= max, each in [low, high] (low excluded when low_open).
DrawnNumber read_drawn_number(const matbase::DocumentNode& node, double low, double high, bool logarithmic,
                              bool low_open = false);

// Every quantity takes one number from the stream, fixed or not, so that the draws after it do
// not shift when a range is narrowed to a value.
double draw(const DrawnNumber& number, SeedStream& draws);
// A whole number in [low, high], each equally likely (one number from the stream too).
int draw_count(const DrawnNumber& count, SeedStream& draws);

}  // namespace matdataset
