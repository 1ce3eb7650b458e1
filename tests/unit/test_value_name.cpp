// The one vocabulary of a machine value (core/interp/value_name.hpp): every
// row of the table spelled, parsed and spelled again the same, and the names
// refused as before.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "core/interp/value_name.hpp"

using namespace pupitre;

namespace {
MachineProfile machine(bool lathe) {
    MachineProfile m;
    m.lathe = lathe;
    m.correctors = 255;
    for (int a = 0; a < kAxes; ++a) m.axes[size_t(a)].present = true;
    return m;
}
}  // namespace

TEST(ValueName, EveryRowRoundTrips) {
    for (const CorrField& f : corr_fields()) {
        for (int d : {1, 12, 255}) {
            std::string text = "D" + std::to_string(d) + "." + std::string(f.text);
            ValueName n;
            ASSERT_TRUE(parse_value_name(text, machine(f.lathe), n)) << text;
            EXPECT_EQ(n.kind, ValueName::Kind::corrector);
            EXPECT_EQ(n.number, d);
            EXPECT_EQ(n.field, &f) << text;
            EXPECT_EQ(format_value_name(n), text);
            // The store's names: either machine's field, but no other spelling.
            ValueName any;
            EXPECT_EQ(parse_value_name(text, any), f.stored) << text;
        }
        EXPECT_EQ(corr_field(f.text, f.lathe), &f);
        if (f.e_family >= 0) {
            EXPECT_EQ(corr_field_of_e(f.e_family, f.lathe), &f);
        }
        EXPECT_EQ(value_unit("D1." + std::string(f.text)),
                  f.unit == ValueUnit::whole ? ValueUnit::whole : ValueUnit::radius);
    }
}

TEST(ValueName, EachMachineHasItsFields) {
    std::string lathe, mill;
    for (const CorrField& f : corr_fields())
        if (f.shown) (f.lathe ? lathe : mill) += std::string(f.text) + " ";
    EXPECT_EQ(lathe, "X Z R C DX DZ ");
    EXPECT_EQ(mill, "L R DL DR ");
    for (int fam = 0; fam <= 5; ++fam) {
        ASSERT_NE(corr_field_of_e(fam, true), nullptr);
        ASSERT_NE(corr_field_of_e(fam, false), nullptr);
    }
    EXPECT_EQ(corr_field_of_e(3, true)->unit, ValueUnit::diameter);  // DX
    EXPECT_EQ(corr_field_of_e(1, false)->member, &Corrector::tip);   // A
}

TEST(ValueName, OriginsAndParametersRoundTrip) {
    for (std::string_view o : kOriginNames)
        for (char a : kAxisNames) {
            std::string text = std::string(o) + "." + a;
            ValueName n;
            ASSERT_TRUE(parse_value_name(text, n)) << text;
            EXPECT_EQ(n.kind, ValueName::Kind::origin);
            EXPECT_EQ(n.axis, axis_of(a));
            EXPECT_EQ(format_value_name(n), text);
            EXPECT_EQ(value_unit(text),
                      is_rotary(axis_of(a)) ? ValueUnit::angle : ValueUnit::radius);
        }
    for (const char* text : {"L0", "L5", "L959", "E80000", "E50003"}) {
        ValueName n;
        ASSERT_TRUE(parse_value_name(text, n)) << text;
        EXPECT_EQ(format_value_name(n), text);
    }
}

TEST(ValueName, RefusesWhatTheRoomsRefused) {
    ValueName n;
    // Unknown fields and origins, a field of the other machine.
    for (const char* bad : {"D1.Q", "D1.", "D1.x", "D1.DY", "PREF.Q", "PREF.XY", "DEC2.X", "pref.X",
                            "PREF", "D1", "X", ""})
        EXPECT_FALSE(parse_value_name(bad, n)) << bad;
    EXPECT_FALSE(parse_value_name("D1.DL", machine(true), n));
    EXPECT_FALSE(parse_value_name("D1.L", machine(true), n));
    EXPECT_FALSE(parse_value_name("D1.X", machine(false), n));
    EXPECT_FALSE(parse_value_name("D1.DX", machine(false), n));
    EXPECT_TRUE(parse_value_name("D1.TIP", machine(false), n));
    EXPECT_FALSE(parse_value_name("D1.TIP", n));  // the store keeps A
    // Bad numbers.
    for (const char* bad : {"D0.X", "D256.X", "D-1.X", "D+1.X", "D1x.X", "Dx.X", "D.X", "D1.5.X",
                            "L", "Lx", "L-1", "L1.5", "E", "E1e3"})
        EXPECT_FALSE(parse_value_name(bad, n)) << bad;
    MachineProfile small = machine(true);
    small.correctors = 99;
    EXPECT_TRUE(parse_value_name("D99.X", small, n));
    EXPECT_FALSE(parse_value_name("D100.X", small, n));
    small.axes[size_t(axis_of('Y'))].present = false;
    EXPECT_FALSE(parse_value_name("PREF.Y", small, n));
}

TEST(ValueName, ACorrectorsNameIsRefusedByTheNumberThenTheField) {
    MachineProfile lathe = machine(true), mill = machine(false);
    lathe.correctors = 99;
    ValueName n;
    EXPECT_EQ(parse_corrector_name("D99.DX", lathe, n), NameFault::none);
    EXPECT_EQ(n.number, 99);
    EXPECT_EQ(n.field, corr_field("DX", true));
    EXPECT_EQ(parse_corrector_name("D1.TIP", mill, n), NameFault::none);
    EXPECT_EQ(n.field->member, &Corrector::tip);
    EXPECT_EQ(parse_corrector_name("D1.C", mill, n),
              NameFault::none);  // not settable: the caller's
    // The number first: a bad one is refused as such whatever the field.
    for (const char* bad : {"D100.X", "D0.X", "D100.Q", "D1e0.X", "Dx.X", "D.X", "D1", "D123",
                            "DEC2.X", "DEC1.Q", "X.X", ""})
        EXPECT_EQ(parse_corrector_name(bad, lathe, n), NameFault::number) << bad;
    for (const char* bad : {"D1.Q", "D1.", "D1.5.X", "D1.L", "D1.TIP", "D1.x"})
        EXPECT_EQ(parse_corrector_name(bad, lathe, n), NameFault::field) << bad;
    EXPECT_EQ(parse_corrector_name("D1.X", mill, n), NameFault::field);
    // What the full parser reads on a machine, this one reads the same.
    for (const CorrField& f : corr_fields()) {
        std::string text = corrector_name(7, f.text);
        ValueName a, b;
        MachineProfile m = machine(f.lathe);
        EXPECT_EQ(parse_corrector_name(text, m, a) == NameFault::none, parse_value_name(text, m, b))
            << text;
        EXPECT_EQ(a.field, b.field) << text;
    }
}

TEST(ValueName, ACorrectorsNameIsSpeltWithTheFieldAsTyped) {
    EXPECT_EQ(corrector_name(3, "X"), "D3.X");
    EXPECT_EQ(corrector_name(12, "Q"), "D12.Q");  // for a refusal to quote
    EXPECT_EQ(corrector_name(1, ""), "D1.");
    EXPECT_EQ(corrector_name(255, "DR"),
              format_value_name(ValueName::corrector(255, corr_field("DR", false))));
}

TEST(ValueName, TheUnitOfANameTheVocabularyRefusesIsALength) {
    EXPECT_EQ(value_unit("D3.C"), ValueUnit::whole);
    EXPECT_EQ(value_unit("PREF.C"), ValueUnit::angle);
    EXPECT_EQ(value_unit("DEC3.B"), ValueUnit::angle);
    for (const char* odd : {"D0.C", "D256.C", "X.C", "PREF.XC", "PREF.", "L5", "E80000", ""})
        EXPECT_EQ(value_unit(odd), ValueUnit::radius) << odd;
}

TEST(ValueName, EachGaugeHasItsWear) {
    std::string lathe, mill;
    for (const CorrField& f : corr_fields())
        if (f.wear) (f.lathe ? lathe : mill) += std::string(f.text) + " ";
    EXPECT_EQ(lathe, "DX DZ ");
    EXPECT_EQ(mill, "DL DR ");
    EXPECT_EQ(gauge_field(GaugeAxis::x, false, true), corr_field("X", true));
    EXPECT_EQ(gauge_field(GaugeAxis::x, true, true), corr_field("DX", true));
    EXPECT_EQ(gauge_field(GaugeAxis::z, false, true), corr_field("Z", true));
    EXPECT_EQ(gauge_field(GaugeAxis::z, true, true), corr_field("DZ", true));
    EXPECT_EQ(gauge_field(GaugeAxis::tool_axis, false, false), corr_field("L", false));
    EXPECT_EQ(gauge_field(GaugeAxis::tool_axis, true, false), corr_field("DL", false));
    EXPECT_EQ(gauge_field(GaugeAxis::x, false, false), nullptr);
    EXPECT_EQ(gauge_field(GaugeAxis::tool_axis, false, true), nullptr);
    EXPECT_EQ(gauge_field(GaugeAxis::none, false, true), nullptr);  // R is no gauge
}
