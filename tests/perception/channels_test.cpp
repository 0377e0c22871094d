// Table 1 of the paper (section 5), row by row, against channels.hpp.
#include "tactus/perception/channels.hpp"

#include <gtest/gtest.h>

namespace tactus::perception {
namespace {

TEST(Channels, MatchThePapersTable1) {
    struct Row {
        Channel channel;
        const char *name, *full_name, *fibre, *receptor;
        double density;
        const char* sensation;
        double low, high, best_low, best_high;
        ResponseShape shape;
    };
    // Transcribed from paper.txt, Table 1 ("Vibrotactile channel characteristics").
    const Row table1[] = {
        {Channel::P, "P", "Pacinian", "FAII", "Pacinian", 21, "vibration", 40, 500, 250, 300,
         ResponseShape::u_shape},
        {Channel::NPI, "NPI", "Non-Pacinian I", "FAI", "Meissner", 140, "flutter", 2, 40, 25, 40,
         ResponseShape::flat},
        {Channel::NPII, "NPII", "Non-Pacinian II", "SAII", "Ruffini", 49, "unknown", 100, 500, 150,
         400, ResponseShape::u_shape},
        {Channel::NPIII, "NPIII", "Non-Pacinian III", "SAI", "Merkel", 70, "pressure", 0.4, 3.0,
         0.4, 1.0, ResponseShape::flat},
    };
    ASSERT_EQ(kChannels.size(), std::size(table1));
    for (const Row& r : table1) {
        const ChannelInfo& c = info(r.channel);
        EXPECT_EQ(c.channel, r.channel);
        EXPECT_EQ(c.name, r.name);
        EXPECT_EQ(c.full_name, r.full_name);
        EXPECT_EQ(c.fibre, r.fibre);
        EXPECT_EQ(c.receptor, r.receptor);
        EXPECT_EQ(c.innervation_per_cm2, r.density) << r.name;
        EXPECT_EQ(c.sensation, r.sensation);
        EXPECT_EQ(c.range_low_hz, r.low) << r.name;
        EXPECT_EQ(c.range_high_hz, r.high) << r.name;
        EXPECT_EQ(c.best_low_hz, r.best_low) << r.name;
        EXPECT_EQ(c.best_high_hz, r.best_high) << r.name;
        EXPECT_EQ(c.shape, r.shape) << r.name;
        // Prime sensitivity lies inside the frequency range.
        EXPECT_GE(c.best_low_hz, c.range_low_hz) << r.name;
        EXPECT_LE(c.best_high_hz, c.range_high_hz) << r.name;
    }
    EXPECT_EQ(info(Channel::NPI).shape_note, "notch at 30 Hz");  // Table 1, note 3
    // Section 5.2: NPI has the highest density, twice the next (NPIII).
    EXPECT_EQ(info(Channel::NPI).innervation_per_cm2, 2 * info(Channel::NPIII).innervation_per_cm2);
}

}  // namespace
}  // namespace tactus::perception
