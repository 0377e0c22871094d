#include "tactus/post/flattening_inputs.hpp"

namespace tactus {

FlatteningDesign flattening_inputs(const Settings& s) {
    return {.low_hz = s[P::post_band_low_hz],
            .high_hz = s[P::post_band_high_hz],
            .strength = s[P::post_flatten_strength],
            .range_db = s[P::post_flatten_range_db],
            .contact_area_cm2 = s[P::perception_contact_area_cm2],
            .level_db = s[P::post_flatten_level_db]};
}

}  // namespace tactus
