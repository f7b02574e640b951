"""candela.render, candela.bench and candela.Error as a Python program meets them (run from the build tree with
PYTHONPATH at the module; CANDELA_EXECUTABLE names the command, whose image the module's must equal)."""

import os
import pathlib
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import numpy as np

import candela

TINY = dict(width=32, height=24, spp=4, backend="cpu")


def read_pfm(path):
    with open(path, "rb") as f:
        assert f.readline() == b"PF\n"
        width, height = map(int, f.readline().split())
        assert float(f.readline()) < 0  # little-endian
        pixels = np.frombuffer(f.read(), dtype="<f4").reshape(height, width, 3)
    return pixels[::-1]  # rows bottom to top in the file


class RenderTest(unittest.TestCase):
    def test_returns_linear_float32_height_by_width_by_3(self):
        image = candela.render("cornell-box", **TINY)
        self.assertEqual(image.shape, (24, 32, 3))
        self.assertEqual(image.dtype, np.float32)
        self.assertTrue(np.isfinite(image).all())
        self.assertGreater(image.mean(), 0.01)

    def test_the_array_shares_the_rendered_pixels(self):
        image = candela.render("cornell-box", **TINY)
        self.assertFalse(image.flags.owndata)  # a view of the render's buffer, which its base keeps alive
        self.assertTrue(image.flags.writeable)
        self.assertTrue(image.flags.c_contiguous)
        image[0, 0] = 5.0
        self.assertEqual(image[0, 0, 1], 5.0)

    def test_equals_the_command_bit_for_bit(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "box.pfm")
            subprocess.run([os.environ["CANDELA_EXECUTABLE"], "render", "cornell-box", "--width", "32", "--height",
                            "24", "--spp", "4", "--seed", "3", "--max-depth", "5", "--backend", "cpu", "--no-cache",
                            "-o", path], check=True, capture_output=True)
            expected = read_pfm(path)
        image = candela.render("cornell-box", width=32, height=24, spp=4, seed=3, max_depth=5, backend="cpu")
        np.testing.assert_array_equal(image, expected)

    def test_a_path_object_names_a_scene(self):
        with self.assertRaisesRegex(candela.Error, r"^/nowhere/x.obj: cannot open"):
            candela.render(pathlib.Path("/nowhere/x.obj"))

    def test_aovs_come_as_a_dict_of_arrays(self):
        image, aovs = candela.render("cornell-box", aovs=["albedo", "normal", "depth"], denoise="atrous", **TINY)
        self.assertEqual(image.shape, (24, 32, 3))
        self.assertEqual(sorted(aovs), ["albedo", "depth", "normal"])
        self.assertEqual(aovs["albedo"].shape, (24, 32, 3))
        self.assertEqual(aovs["depth"].shape, (24, 32))
        self.assertGreater(aovs["depth"].mean(), 0.0)

    def test_the_callback_sees_each_sample_and_false_ends_the_render(self):
        seen = []

        def progress(p):
            seen.append((p.samples, p.spp))
            if p.samples == 2:
                self.assertEqual(p.image().shape, (24, 32, 3))
            return p.samples < 3

        candela.render("cornell-box", callback=progress, **dict(TINY, spp=16))
        self.assertEqual(seen, [(1, 16), (2, 16), (3, 16)])

    def test_a_callback_returning_none_goes_on(self):
        calls = []
        candela.render("cornell-box", callback=lambda p: calls.append(p.samples), **TINY)
        self.assertEqual(calls, [1, 2, 3, 4])

    def test_the_progress_is_readable_only_during_the_callback(self):
        kept = []
        candela.render("cornell-box", callback=kept.append, **TINY)
        with self.assertRaisesRegex(candela.Error, "only during its callback"):
            kept[0].image()

    def test_an_exception_in_the_callback_ends_the_render_and_is_raised(self):
        calls = []

        def fails(p):
            calls.append(p)
            raise ValueError("enough")

        with self.assertRaisesRegex(ValueError, "enough"):
            candela.render("cornell-box", callback=fails, **TINY)
        self.assertEqual([p.samples for p in calls], [1])
        with self.assertRaisesRegex(candela.Error, "only during its callback"):
            calls[0].image()  # the render is over: its film is gone

    def test_errors_are_candela_errors_with_the_commands_message(self):
        self.assertTrue(issubclass(candela.Error, RuntimeError))
        with self.assertRaisesRegex(candela.Error, r"^unknown scene 'nowhere': not a file, nor a built-in scene"):
            candela.render("nowhere", **TINY)
        with self.assertRaisesRegex(candela.Error, "magic"):
            candela.render("cornell-box", denoise="magic", **TINY)
        with self.assertRaisesRegex(candela.Error, r"^width 0 is not in \[1, 16384\]$"):
            candela.render("cornell-box", **dict(TINY, width=0))
        with self.assertRaisesRegex(TypeError, "scene"):
            candela.render(42)

    def test_the_gil_is_released_while_rendering(self):
        # While another thread renders, this one keeps running: the longest pause between its steps stays far
        # below the render's time (holding the GIL, the render would stop this thread for all of it).
        done = threading.Event()

        def work():
            candela.render("cornell-box", width=96, height=96, spp=32, backend="cpu", threads=1)
            done.set()

        worker = threading.Thread(target=work)
        start = time.monotonic()
        worker.start()
        longest, last = 0.0, time.monotonic()
        while not done.is_set():
            time.sleep(0.001)
            now = time.monotonic()
            longest, last = max(longest, now - last), now
        worker.join()
        elapsed = time.monotonic() - start
        self.assertGreater(elapsed, 0.3, "the render was too quick to tell")
        self.assertLess(longest, elapsed / 4)

    def test_renders_from_several_threads_at_once_give_each_its_own_image(self):
        # Four threads render at the same time, two scenes and two seeds, one scene object shared by two of them:
        # each gets exactly the image it gets alone.
        shared = candela.load("cornell-box")
        jobs = [(shared, 0), (shared, 5), ("cornell-spheres", 0), ("cornell-spheres", 5)]
        alone = [candela.render(scene, **dict(TINY, seed=seed, threads=1)) for scene, seed in jobs]
        together = [None] * len(jobs)
        errors = []
        start = threading.Barrier(len(jobs))

        def work(i):
            scene, seed = jobs[i]
            try:
                start.wait()
                together[i] = candela.render(scene, **dict(TINY, seed=seed, threads=1))
            except Exception as e:  # reported below: an assertion in a thread would pass unseen
                errors.append(e)

        workers = [threading.Thread(target=work, args=(i,)) for i in range(len(jobs))]
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        self.assertEqual(errors, [])
        for i in range(len(jobs)):
            np.testing.assert_array_equal(together[i], alone[i])
        self.assertFalse(np.array_equal(alone[0], alone[1]))

    def test_ctrl_c_ends_the_render_with_keyboard_interrupt(self):
        interrupt = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
        start = time.monotonic()
        interrupt.start()
        with self.assertRaises(KeyboardInterrupt):
            candela.render("cornell-box", width=256, height=256, spp=1 << 20, backend="cpu")
        self.assertLess(time.monotonic() - start, 60)

    def test_bench_returns_the_commands_numbers(self):
        numbers = candela.bench("cornell-box", width=32, height=24, spp=2, backend="cpu", warmup=1)
        self.assertEqual(numbers["scene"], "cornell-box")
        self.assertEqual(numbers["spp"], 2)
        self.assertEqual(numbers["warmup_frames"], 1)
        self.assertGreater(numbers["mrays_per_s"], 0.0)

    def test_a_loaded_scene_renders_several_times(self):
        scene = candela.load("cornell-box")
        self.assertEqual(scene.name, "cornell-box")
        a = candela.render(scene, **TINY)
        b = candela.render(scene, **dict(TINY, seed=1))
        self.assertFalse(np.array_equal(a, b))


if __name__ == "__main__":
    unittest.main()
