#include "frontends/deform/deform_options.h"

#include <gtest/gtest.h>

#include "optim/errors.h"

namespace sa {
namespace {

TEST(DeformOptions, DefaultsAreThePapers) {
    const DeformOptions o;
    EXPECT_NO_THROW(o.validate());
    EXPECT_EQ(o.mu, 1000.0);
    EXPECT_EQ(o.initialization, Initialization::kClosestRotation);
    EXPECT_EQ(o.conformal_bound, kInfinity);
    EXPECT_EQ(o.volumetric_bound, kInfinity);
}

TEST(DeformOptions, BadFieldsAreNamed) {
    auto expect_bad = [](DeformOptions o, const std::string& field) {
        try {
            o.validate();
            ADD_FAILURE() << field << " accepted";
        } catch (const InvalidArgumentError& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
    };
    DeformOptions o;
    o.conformal_bound = 1.0;
    expect_bad(o, "conformal_bound");
    o = {};
    o.volumetric_bound = std::nan("");
    expect_bad(o, "volumetric_bound");
    o = {};
    o.optimal_bound = true;
    o.volumetric_bound = 3.0;
    expect_bad(o, "optimal_bound");
    o = {};
    o.mu = -1.0;
    expect_bad(o, "mu");
    o = {};
    o.start.tolerance = -1.0;
    expect_bad(o, "tolerance");
    o = {};
    o.optimal_bound = true;
    EXPECT_NO_THROW(o.validate());
}

}  // namespace
}  // namespace sa
