// A correction as typed after --correct OFFSET: "x=+0.2,z=-0.2" — axes x, y, z, each at most
// once, values in mm with an optional sign; axes left out are 0.
#pragma once
#include <string_view>

#include <Eigen/Core>

namespace imess::messoffs {

// Throws client::UsageError saying what was wrong and the accepted form.
Eigen::Vector3d parse_correction_spec(std::string_view text);

}  // namespace imess::messoffs
