#include "matdataset/maker/drawn_number.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace matdataset {

DrawnNumber read_drawn_number(const matbase::DocumentNode& node, double low, double high, bool logarithmic,
                              bool low_open) {
  if (!node.is_list()) return DrawnNumber::value(node.number_in(low, high, low_open), logarithmic);
  const std::vector<matbase::DocumentNode> ends = node.items(2, "a number or a range [min, max]");
  const double a = ends[0].number_in(low, high, low_open), b = ends[1].number_in(low, high, low_open);
  if (a > b) node.fail(fmt::format("a range [min, max] with min <= max (got [{}, {}]; swap them)", a, b));
  return {a, b, logarithmic};
}

double draw(const DrawnNumber& number, SeedStream& draws) {
  const double u = draws.uniform();
  if (number.low == number.high) return number.low;
  if (number.logarithmic)
    return std::exp(std::log(number.low) + u * (std::log(number.high) - std::log(number.low)));
  return number.low + u * (number.high - number.low);
}

int draw_count(const DrawnNumber& count, SeedStream& draws) {
  const double u = draws.uniform();
  const double span = count.high - count.low + 1.0;
  return static_cast<int>(count.low + std::min(std::floor(u * span), span - 1.0));
}

}  // namespace matdataset
