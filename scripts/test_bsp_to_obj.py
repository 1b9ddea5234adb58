"""Tests scripts/bsp_to_obj.py on a map it writes itself: which surfaces are kept, the turn to
metres with +Y up, a patch's tessellation, the spawn cameras, and a corrupt file's error.

    python3 -m unittest discover -s scripts -p 'test_*.py'
"""
import importlib.util
import pathlib
import struct
import tempfile
import unittest

HERE = pathlib.Path(__file__).parent
spec = importlib.util.spec_from_file_location("bsp_to_obj", HERE / "bsp_to_obj.py")
bsp_to_obj = importlib.util.module_from_spec(spec)
spec.loader.exec_module(bsp_to_obj)


def face(shader, kind, first, count, first_index=0, index_count=0, size=(0, 0)):
    return struct.pack("<12i12f2i", shader, -1, kind, first, count, first_index, index_count,
                       0, 0, 0, 0, 0, *([0.0] * 12), *size)


def vertex(x, y, z):
    return struct.pack("<3f2f2f3f4B", x, y, z, 0, 0, 0, 0, 0, 0, 1, 255, 255, 255, 255)


def make_map():
    """A floor quad, a patch bent up in its middle row, and a sky quad, a water quad and a
    billboard that the conversion leaves out; one spawn point facing +Y."""
    entities = b'{ "classname" "worldspawn" }\n' \
        b'{ "classname" "info_player_deathmatch" "origin" "0 0 0" "angle" "90" }\n\0'
    shaders = b"".join(struct.pack("<64sii", name, flags, contents) for name, flags, contents in [
        (b"textures/floor", 0, 1),
        (b"textures/sky", bsp_to_obj.SURF_SKY, 0),
        (b"textures/water", 0, 32),
    ])
    quad = [(0, 0, 0), (100, 0, 0), (100, 100, 0), (0, 100, 0)]
    patch = [(x, y, 40 if y == 50 else 0) for y in (0, 50, 100) for x in (200, 250, 300)]
    points = quad + patch + quad + quad + quad
    vertices = b"".join(vertex(*p) for p in points)
    meshverts = struct.pack("<6i", 0, 1, 2, 0, 2, 3)
    faces = b"".join([
        face(0, bsp_to_obj.POLYGON, 0, 4, 0, 6),
        face(0, bsp_to_obj.PATCH, 4, 9, size=(3, 3)),
        face(1, bsp_to_obj.POLYGON, 13, 4, 0, 6),
        face(2, bsp_to_obj.POLYGON, 17, 4, 0, 6),
        face(0, 4, 21, 4),
    ])
    lumps = {0: entities, 1: shaders, 10: vertices, 11: meshverts, 13: faces}
    header, body, offset = [], b"", 8 + 17 * 8
    for i in range(17):
        data = lumps.get(i, b"")
        header.append(struct.pack("<ii", offset + len(body), len(data)))
        body += data
    return b"IBSP" + struct.pack("<i", 46) + b"".join(header) + body


class BspToObj(unittest.TestCase):
    def test_keeps_the_solid_surfaces_and_tessellates_the_patch(self):
        triangles, skipped = bsp_to_obj.convert(make_map(), steps=2)
        # The floor's two triangles and the patch's 2 x 2 x 2; sky, water and billboard go.
        self.assertEqual(len(triangles), 2 + 8)
        self.assertEqual(skipped, 3)
        # The middle row of the patch, half way along: a quadratic Bezier's middle is a
        # quarter of each end and half the middle control point.
        heights = {corner[2] for tri in triangles[2:] for corner in tri}
        self.assertEqual(heights, {0.0, 20.0})

    def test_writes_metres_with_y_up_and_welds_shared_corners(self):
        triangles, _ = bsp_to_obj.convert(make_map(), steps=2)
        with tempfile.TemporaryDirectory() as tmp:
            path = pathlib.Path(tmp) / "map.obj"
            vertices, faces = bsp_to_obj.write_obj(triangles, path, "test")
            lines = path.read_text().splitlines()
        # The floor's quad has 4 corners, the patch's grid of 3 x 3 points 9.
        self.assertEqual((vertices, faces), (4 + 9, 10))
        self.assertIn("v 2.5400 0.0000 -2.5400", lines)  # Quake's (100, 100, 0)
        self.assertIn("v 6.3500 0.5080 -1.2700", lines)  # the patch's middle, 20 up
        self.assertEqual(sum(line.startswith("f ") for line in lines), 10)

    def test_spawn_points_become_cameras_at_eye_height(self):
        (camera,) = bsp_to_obj.spawn_cameras(make_map())
        self.assertEqual(camera["eye"], [0.0, 0.66, 0.0])
        # Facing +Y in the map, -Z once +Z is turned to +Y.
        self.assertEqual(camera["target"], [0.0, 0.66, -2.54])

    def test_a_corrupt_map_is_an_error_that_names_the_format(self):
        with self.assertRaises(SystemExit) as error:
            bsp_to_obj.convert(b"IBSP" + struct.pack("<i", 47) + bytes(136), steps=2)
        self.assertIn("IBSP 46", str(error.exception))


if __name__ == "__main__":
    unittest.main()
