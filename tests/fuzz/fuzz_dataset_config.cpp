// make_dataset's configuration reader on arbitrary YAML or JSON: every value is checked where it
// is read, so bad input leaves only as matbase::InputError (a std::runtime_error) naming the key.
#include "fuzz_file.h"
#include "matdataset/maker/dataset_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fuzz_file(data, size, ".yaml", [](const std::string& path) { matdataset::load_config(path, {}); });
}
