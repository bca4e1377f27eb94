#include "matrender/render_setting_reading.h"

namespace matrender {

void read_render_setting(const matbase::DocumentNode& value, const RenderSettingDeclaration& setting,
                         RenderSettings& settings) {
  switch (setting.form) {
    case SettingForm::WholeNumber:
      assign_number(settings, setting,
                    static_cast<double>(value.whole_number(static_cast<int64_t>(setting.least),
                                                           static_cast<int64_t>(setting.most))));
      return;
    case SettingForm::Number:
      assign_number(settings, setting,
                    value.number_where([&setting](double v) { return !number_problem(setting, v); }, expectation(setting)));
      return;
    case SettingForm::Switch: assign_switch(settings, setting, value.boolean()); return;
    case SettingForm::Choice: {
      const std::vector<std::string> choices(setting.choices.begin(), setting.choices.end());
      assign_choice(settings, setting, value.choice(choices));
      return;
    }
  }
}

}  // namespace matrender
