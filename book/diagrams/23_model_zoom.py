"""Chapter 23: the glTF test model's two cubes, enlarged.

Drawn from the reviewed test picture tests/golden/23_materials_model.png
(assets/gltf/pbr_cubes.gltf, headless at 320x240 after 10 frames): the crop
around both cubes, every pixel enlarged 5 times, so that what each of the
five textures does can be found: the checker (base colour), the studs'
polish (metallic-roughness), their relief and highlights (normal map), the
darker rings at their feet (occlusion) and the glowing ring (emissive).
The left cube has TANGENT, the right one not.
"""

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

LEFT, TOP, CROP_W, CROP_H, ZOOM = 78, 70, 182, 108, 5
X0, Y0 = 45, 50
# The emissive rings, points of the 320x240 picture, each ringed with its diameter.
MARKS = [((122.5, 133.5), 14), ((220, 144), 16)]


def at(point):
    return X0 + (point[0] - LEFT + 0.5) * ZOOM, Y0 + (point[1] - TOP + 0.5) * ZOOM


def main() -> None:
    w, h = CROP_W * ZOOM, CROP_H * ZOOM
    s = Svg(1000, Y0 + h + 120, "Chapter 23: the glTF test model, enlarged 5 times",
            "The two cubes of assets/gltf/pbr_cubes.gltf from the chapter's test picture, each pixel "
            "enlarged 5 times: a red and cream checker, a dark polished metal stud on every square "
            "with a small highlight, a darker ring where each stud meets the square, and a yellow "
            "glowing ring in the middle of each face. The left cube has tangents in the file, the "
            "right one has them made in the shader; both show the same round raised studs, though the cubes stand at different angles.")
    s.text(20, 28, "--model assets/gltf/pbr_cubes.gltf at 320x240, enlarged 5 times", size=14, bold=True)
    enlarged(s, read_png(GOLDEN / "23_materials_model.png"), LEFT, TOP, CROP_W, CROP_H, X0, Y0, ZOOM)
    for point, diameter in MARKS:
        cx, cy = at(point)
        s.circle(cx, cy, diameter * ZOOM / 2 + 4, stroke="#ffffff", width=2.5, dash="7 5")
    s.text(X0 + (117 - LEFT) * ZOOM, Y0 + h + 24, "left: TANGENT from the file", size=13,
           anchor="middle")
    s.text(X0 + (212 - LEFT) * ZOOM, Y0 + h + 24, "right: no TANGENT, the frame made from dFdx, dFdy",
           size=13, anchor="middle")
    s.lines(20, Y0 + h + 58, [
        "Ringed (dashed): the emissive texture, a ring that glows yellow whatever the light. On every "
        "square a stud: dark",
        "polished metal (metallic-roughness) with a small white highlight, its round relief the normal "
        "map; the darker rim",
        "where it meets the square is the occlusion texture. The red and cream checker is the base "
        "colour."],
        size=12.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
