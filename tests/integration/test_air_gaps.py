"""Narrow air gaps (Resources/samples/gaps, made by scripts/make_samples.py): a sheet folded back over itself, the air
between its two legs about as wide as the sheet is thick or narrower. Open hems of a 1 mm sheet (the air 1.0 and 0.6
wide; the faces split; in metres), of a 2 mm sheet (the air 1.5 wide), and a spring clip (1.5 thick, 1.2 apart).
Bubbles packed 1.5 walls apart reached across the air: the Delaunay tets joined a leg's nodes to the other leg's, the
chordal surface crossed the air (refused, exit 4, or hexes inverted and the volume 6-23 % high, exit 6). A wall facing
the solid across a narrow gap now gets bubbles no wider than the gap (geometry/wall_sides airGap, bubbles gapLimit).

Each part with 2 and 3 layers, checked on the written .inp with tools of their own: every element an 8-node hex of
positive volume; the scaled Jacobian of every hex (min >= 0.5, avg >= 0.99); the mesh volume within 1.5 % of the CAD
volume Gmsh's OpenCASCADE computes (a mesh bridging the gap is 6-23 % high); every boundary node within 1e-6 mm of the
CAD face it is grouped on; the part's topology (a mesh joined across the gap has another).

Run by CTest as: /usr/bin/python3 test_air_gaps.py --hexlayer PATH --source DIR
"""
import harness
from sample_mesh import MeshTest, check_sample

# Measured: minima 0.64 (hem_metres) to 0.87 (hem_open), averages 0.991-0.998; volumes -0.51 % to -0.14 %.
PARTS = ["hem_open", "hem_narrow", "hem_thick", "hem_split", "hem_metres", "spring_clip"]
LAYERS = (2, 3)


class AirGaps(MeshTest):
    def check(self, part, layers):
        check_sample(self, "gaps", part, layers, (0.5, 0.99), 0.015, 1.0)

    def test_every_hem(self):
        self.check_each(PARTS, LAYERS)


if __name__ == "__main__":
    harness.main()
