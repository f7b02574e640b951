"""candela.Scene: scenes built from NumPy arrays, and the errors that name what is wrong with them."""

import unittest

import numpy as np

import candela

QUAD = np.array([[0, 2, 1], [0, 3, 2]], dtype=np.uint32)  # faces +y over the corners below


def square(size, height):
    s = size / 2
    return np.array([[-s, height, -s], [s, height, -s], [s, height, s], [-s, height, s]], dtype=np.float32)


def lit_floor():
    scene = candela.Scene("floor")
    white = scene.add_material(type="diffuse", base_color=(0.8, 0.8, 0.8))
    lamp = scene.add_material(type="diffuse", base_color=(0, 0, 0), emission=(10, 10, 10))
    scene.add_mesh(square(4, 0), QUAD, material=white)
    scene.add_mesh(square(1, 2), QUAD[:, ::-1], material=lamp)  # reversed: the lamp faces down
    scene.set_camera((0, 3, 5), (0, 0, 0), fov=40)
    return scene


class SceneTest(unittest.TestCase):
    def test_an_emissive_mesh_lights_the_floor(self):
        image = candela.render(lit_floor(), width=32, height=24, spp=8, backend="cpu")
        self.assertGreater(image[16, 16, 0], 0.1)  # the floor under the lamp
        self.assertEqual(image[0, 0, 0], 0.0)  # above the floor's far edge: nothing there, no sky

    def test_a_point_light_and_a_sky_light_too(self):
        scene = candela.Scene()
        scene.add_mesh(square(4, 0), QUAD, material=scene.add_material())
        dark = candela.render(scene, width=16, height=16, spp=4, backend="cpu")
        scene.add_point_light((0, 1, 0), (5, 5, 5))
        lit = candela.render(scene, width=16, height=16, spp=4, backend="cpu")
        scene.set_environment((0.5, 0.5, 0.5))
        sky = candela.render(scene, width=16, height=16, spp=4, backend="cpu")
        self.assertEqual(dark.max(), 0.0)
        self.assertGreater(lit.mean(), 0.0)
        self.assertGreater(sky.mean(), lit.mean())

    def test_a_transform_moves_the_mesh(self):
        # A second lamp where the first is doubles the light on the floor; moved far below the floor, it adds none.
        def with_second_lamp(transform):
            scene = lit_floor()
            scene.add_mesh(square(1, 2), QUAD[:, ::-1], material=1, transform=transform)
            self.assertEqual(scene.build().triangle_count, 6)
            return candela.render(scene, width=32, height=24, spp=16, backend="cpu")

        below = np.eye(4, dtype=np.float32)
        below[1, 3] = -100.0
        doubled, moved = with_second_lamp(np.eye(4)), with_second_lamp(below)
        self.assertGreater(doubled.mean(), 1.6 * moved.mean())
        self.assertGreater(moved.mean(), 0.0)

    def test_bad_arrays_are_named(self):
        scene = candela.Scene()
        with self.assertRaisesRegex(candela.Error, r"^positions: an array of shape \(n, 3\), not \(4, 2\)$"):
            scene.add_mesh(np.zeros((4, 2), np.float32), QUAD)
        with self.assertRaisesRegex(candela.Error, r"^mesh 0: triangle 1 names vertex 3, beyond its 3 vertices$"):
            scene.add_mesh(square(1, 0)[:3], QUAD)
        with self.assertRaisesRegex(candela.Error, r"^unknown material type 'velvet'"):
            scene.add_material(type="velvet")
        with self.assertRaisesRegex(candela.Error, r"^transform: a 3x4 or 4x4 matrix, not \(3, 3\)$"):
            scene.add_mesh(square(1, 0), QUAD, transform=np.eye(3))
        scene.add_mesh(square(1, 0), QUAD, material=3)
        with self.assertRaisesRegex(candela.Error, r"names material 3, but 0 materials were added"):
            candela.render(scene, width=8, height=8, spp=1)


if __name__ == "__main__":
    unittest.main()
