// The flattening filter's design inputs read from the settings (the post chain's band and the
// post_flatten_* and perception_contact_area_cm2 parameters). Any thread.
#pragma once

#include "tactus/params/params.hpp"
#include "tactus/post/flattening_filter.hpp"

namespace tactus {

FlatteningDesign flattening_inputs(const Settings& s);

}  // namespace tactus
