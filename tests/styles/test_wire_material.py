"""The wire material per atom type (common/plugin_material.h): fix wire/elastic, pair_style
wire/contact and fix wire/wall read E and ν from the keywords E, nu, else from LIGGGHTS'
fix property/global youngsModulus / poissonsRatio peratomtype, else Table 1; and the error
messages for bad property values."""

import numpy as np

from liggghts_run import DeckTestCase, main, run

HEADER = """
units           lj
atom_style      wire
boundary        f f f
newton          off
region          box block -3 3 -3 3 -1 5
create_box      2 box
"""

# A 3-turn coil of type-2 beads falls onto a floor and onto itself: stretching, bending,
# wire–wire and wire–wall contacts all act. {materials} defines the property/global fixes,
# {elastic}, {pair} and {wall} the keywords of each style.
COIL = HEADER + """
{materials}
create_wire     2 loop 0 0 0.4 0.5 3 0.25 segment 0.2
pair_style      wire/contact {pair}
pair_coeff      * *
neighbor        0.1 bin
fix             el all wire/elastic {elastic}
fix_modify      el energy yes
fix             int all nve/gear forces velocity
fix             g all gravity 1.0 vector 0 0 -1
fix             floor all wire/wall plane 0 0 0 0 0 1 {wall}
timestep        1e-4
compute         c all wire/contacts
compute         en all wire/energy
thermo_style    custom step f_el ke c_c[1] c_c[2] c_c[4] f_floor[1] f_floor[2] f_floor[3] f_floor[5] c_en[1] c_en[2] c_en[4]
thermo_modify   format float %.17g
thermo          500
run             8000
"""

PROPERTIES = """
fix             m1 all property/global youngsModulus peratomtype {e1} {e2}
fix             m2 all property/global poissonsRatio peratomtype {nu1} {nu2}
"""

COLUMNS = ("el", "KinEng", "c[1]", "c[2]", "c[4]", "floor[1]", "floor[2]", "floor[3]", "floor[5]",
           "en[1]", "en[2]", "en[4]")


class MaterialPerType(DeckTestCase):
    def coil(self, materials="", elastic="", pair="", wall=""):
        r = run(COIL.format(materials=materials, elastic=elastic, pair=pair, wall=wall))
        self.assertRanCleanly(r)
        return r.thermo()

    def assertSameRun(self, reference, other):
        for column in COLUMNS:
            np.testing.assert_allclose(other[column], reference[column], rtol=1e-12, atol=1e-14,
                                       err_msg=column)

    def test_property_global_equals_keywords(self):
        # E = 150, ν = 0.3 by keywords on each style, and by property/global for type 2
        # (type 1, unused, gets values that would show if the wrong type were read)
        keywords = self.coil(elastic="E 150", pair="E 150 nu 0.3", wall="E 150 nu 0.3")
        by_type = self.coil(materials=PROPERTIES.format(e1=1e5, e2=150, nu1=0.45, nu2=0.3))
        self.assertGreater(np.max(keywords["c[1]"]), 0)      # the coil touched itself
        self.assertGreater(np.max(keywords["floor[1]"]), 0)  # and the floor
        self.assertGreater(np.max(keywords["en[2]"]), 0)     # and bent
        self.assertSameRun(keywords, by_type)
        # and the material matters: Table 1 (E = 100, ν = 0) gives another run
        table1 = self.coil()
        self.assertGreater(abs(table1["KinEng"][-1] - keywords["KinEng"][-1]), 1e-6)

    def test_keywords_override_property_global(self):
        keywords = self.coil(elastic="E 150", pair="E 150 nu 0.3", wall="E 150 nu 0.3")
        both = self.coil(materials=PROPERTIES.format(e1=400, e2=400, nu1=0.1, nu2=0.1),
                         elastic="E 150", pair="E 150 nu 0.3", wall="E 150 nu 0.3")
        self.assertSameRun(keywords, both)

    def test_table1_without_either(self):
        table1 = self.coil()
        explicit = self.coil(elastic="E 100", pair="E 100 nu 0", wall="E 100 nu 0")
        self.assertSameRun(table1, explicit)


class BadProperty(DeckTestCase):
    def check(self, materials, styles, message):
        text = HEADER + materials + "create_wire 1 line 0 0 1 1 0 1\n" + styles + "\nrun 1\n"
        self.assertStopsWith(run(text), message)

    def test_negative_modulus(self):
        self.check(PROPERTIES.format(e1=-5, e2=100, nu1=0, nu2=0), "fix el all wire/elastic",
                   "fix wire/elastic (id el): youngsModulus of atom type 1 must be a finite number > 0, got -5")

    def test_poisson_ratio_out_of_range(self):
        self.check(PROPERTIES.format(e1=100, e2=100, nu1=0.2, nu2=0.5), "pair_style wire/contact\npair_coeff * *",
                   "pair wire/contact (id -): poissonsRatio of atom type 2 must be in [0, 0.5), got 0.5")
        self.check(PROPERTIES.format(e1=100, e2=100, nu1=-0.1, nu2=0), "fix w all wire/wall plane 0 0 0 0 0 1",
                   "fix wire/wall (id w): poissonsRatio of atom type 1 must be in [0, 0.5), got -0.1")

    def test_too_few_values(self):
        # (for the fixes, defined after it, LIGGGHTS' fix property/global stops first)
        self.check("fix m1 all property/global youngsModulus peratomtype 100\n",
                   "pair_style wire/contact\npair_coeff * *",
                   "pair wire/contact (id -): fix property/global youngsModulus has 1 value(s), needs one per "
                   "atom type (2)")

    def test_keyword_hides_a_bad_property(self):
        # the keyword wins, so the property is not read for that style
        r = run(HEADER + PROPERTIES.format(e1=-5, e2=-5, nu1=0, nu2=0) +
                "create_wire 1 line 0 0 1 1 0 1\nfix el all wire/elastic E 100\n"
                "fix int all nve/gear\ntimestep 1e-4\nrun 10\n")
        self.assertRanCleanly(r)


if __name__ == "__main__":
    main()
