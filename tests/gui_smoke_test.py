"""GUI smoke test: the editor starts under Xvfb, its real window shows the lit sphere and the
material panel, and it exits cleanly (code 0) on a window-manager close request.
usage: gui_smoke_test.py GLINT OUTPUT_DIR"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import WAIT_SECONDS, XServer, pixel, write_png  # noqa: E402


def looks(shot):
    """What the smoke test expects on screen: name → (holds, the measured value)."""
    width, height, _ = shot
    # The viewport lies between the scene column (330 px) and the material column (360 px); the
    # sphere sits near its centre.
    sphere = pixel(shot, 330 + (width - 330 - 360) // 2, height // 2 - 40)
    background = pixel(shot, 350, 60)
    # The panel: ImGui's dark window with light text on it.
    panel = [pixel(shot, x, y) for x in range(width - 340, width - 20, 2) for y in range(40, 300, 2)]
    bright = sum(1 for p in panel if min(p) > 180)
    return {"sphere": (sphere[0] > 80 and sphere[0] > sphere[1] + 30, sphere),
            "background": (max(background) < 60, background),
            "panel": (bright > 50, bright)}


def main():
    glint, output = sys.argv[1], sys.argv[2]
    os.makedirs(output, exist_ok=True)
    close_helper = os.environ["GLINT_X11_CLOSE"]
    with XServer(1280, 800) as x, tempfile.TemporaryDirectory() as state:
        env = dict(x.env, GLINT_STATE_DIR=state, GLINT_GUI_FAILURE_DIR=output)  # no recovery offer from other runs
        editor = subprocess.Popen([glint], env=env, cwd=output, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        try:
            window = x.find_window("Glint")
            # The first frames (shader compile, ImGui layout) arrive when they arrive: poll for them.
            shot = x.wait_for(lambda image: all(ok for ok, _ in looks(image).values()),
                              "the lit sphere, the dark background and the material panel's text")
            write_png(shot, os.path.join(output, "gui_smoke.png"))
            found = looks(shot)
            subprocess.run([close_helper, window], env=x.env, check=True)
            code = editor.wait(timeout=WAIT_SECONDS)
            assert code == 0, f"editor exited with {code}"
            print(f"ok: sphere {found['sphere'][1]}, panel text pixels {found['panel'][1]}, clean exit")
        finally:
            if editor.poll() is None:
                editor.kill()
                print(editor.communicate()[0])


if __name__ == "__main__":
    main()
