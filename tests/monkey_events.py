"""The monkey's events: a seeded, pure list of what a careless hand does to the editor (clicks,
drags, wheel, keys and shortcuts, typing, undo/redo storms, files opened and dropped, window
resizes, kill -9). Positions are fractions of the window, resolved against its size when the
event runs, so the same seed gives the same list whatever happened before. Runs nothing."""
import random

# Where a hand lands, as fractions of the window (x0, y0, x1, y1): the panels of the default
# 1280×800 layout (scene column on the left, material column on the right), scaled.
REGIONS = {
    "menu_bar": (0.0, 0.0, 1.0, 0.03),
    "scene_column": (0.0, 0.03, 0.26, 0.97),
    "material_column": (0.72, 0.03, 1.0, 0.97),
    "viewport": (0.26, 0.03, 0.72, 0.97),
    "status_bar": (0.0, 0.97, 1.0, 1.0),
}
REGION_WEIGHTS = {"menu_bar": 2, "scene_column": 5, "material_column": 5, "viewport": 4, "status_bar": 1}

# xdotool key names: the editor's shortcuts (app/editor/shortcuts.cpp), dialog keys, and keys a
# hand hits by accident.
SHORTCUTS = ["ctrl+z", "ctrl+shift+z", "ctrl+y", "ctrl+s", "ctrl+shift+s", "ctrl+o", "ctrl+m", "ctrl+n",
             "ctrl+q", "f", "Home", "p", "w", "n", "b", "F12", "F11", "l", "i", "F1", "Right", "Left", "Next",
             "Prior"]
OTHER_KEYS = ["Escape", "Return", "Tab", "space", "BackSpace", "Delete", "Up", "Down", "y", "s", "d", "minus",
              "period", "0", "1", "5", "9", "shift+Tab", "ctrl+a", "ctrl+c", "ctrl+v", "alt+f"]
TYPED_CHARACTERS = "abcdefghijklmnopqrstuvwxyz0123456789.-_ "

# Relative weights of the event kinds (kills are placed separately: a fixed number per run).
KIND_WEIGHTS = {"click": 30, "drag": 18, "wheel": 6, "key": 22, "type": 5, "undo_storm": 4, "open_file": 4,
                "open_mesh": 2, "drop_file": 3, "drop_mid_drag": 2, "resize": 4}

SMALLEST_WINDOW = (320, 240)
LARGEST_WINDOW = (1280, 800)


def _point(rng, region=None):
    region = region or rng.choices(list(REGION_WEIGHTS), weights=list(REGION_WEIGHTS.values()))[0]
    x0, y0, x1, y1 = REGIONS[region]
    return [round(rng.uniform(x0, x1), 4), round(rng.uniform(y0, y1), 4)]


def _event(rng, kind, files, meshes):
    if kind == "click":
        return {"at": _point(rng), "button": rng.choices([1, 3, 2], weights=[8, 2, 1])[0],
                "double": rng.random() < 0.1, "shift": rng.random() < 0.05}
    if kind in ("drag", "drop_mid_drag"):
        start = _point(rng)
        end = _point(rng) if rng.random() < 0.5 else [min(1.0, max(0.0, c + rng.uniform(-0.15, 0.15))) for c in start]
        event = {"from": start, "to": [round(c, 4) for c in end], "button": rng.choices([1, 3, 2], weights=[8, 2, 1])[0],
                 "steps": rng.randint(2, 12)}
        if kind == "drop_mid_drag":
            event["file"] = rng.choice(files)
        return event
    if kind == "wheel":
        return {"at": _point(rng), "button": rng.choice([4, 5]), "clicks": rng.randint(1, 6)}
    if kind == "key":
        return {"key": rng.choice(SHORTCUTS) if rng.random() < 0.6 else rng.choice(OTHER_KEYS)}
    if kind == "type":
        return {"text": "".join(rng.choice(TYPED_CHARACTERS) for _ in range(rng.randint(1, 8)))}
    if kind == "undo_storm":
        return {"undo": rng.randint(3, 30), "redo": rng.randint(0, 30)}
    if kind == "open_file":
        return {"file": rng.choice(files)}
    if kind == "open_mesh":
        return {"file": rng.choice(meshes)}
    if kind == "drop_file":
        return {"file": rng.choice(files), "at": _point(rng)}
    if kind == "resize":
        if rng.random() < 0.2:
            return {"size": list(SMALLEST_WINDOW)}
        if rng.random() < 0.2:
            return {"size": list(LARGEST_WINDOW)}
        return {"size": [rng.randint(SMALLEST_WINDOW[0], LARGEST_WINDOW[0]), rng.randint(SMALLEST_WINDOW[1], LARGEST_WINDOW[1])]}
    raise ValueError(f"unknown event kind {kind}")


def generate(seed, count, kills, files, meshes):
    """The run's events: `count` input events with `kills` kill -9s among them, each a dict with
    its index "i" and "kind". `files` and `meshes` are names (relative to the monkey's file
    folder) that open_file, drop_file and open_mesh pick from."""
    rng = random.Random(seed)
    kill_at = set(rng.sample(range(1, count), min(kills, count - 1))) if count > 1 else set()
    events = []
    for i in range(count):
        if i in kill_at:
            events.append({"i": i, "kind": "kill", "pause": round(rng.uniform(0.0, 2.0), 2)})
            continue
        kind = rng.choices(list(KIND_WEIGHTS), weights=list(KIND_WEIGHTS.values()))[0]
        event = {"i": i, "kind": kind, **_event(rng, kind, files, meshes)}
        event["pause"] = round(rng.uniform(0.01, 0.15), 3)  # seconds before the next event
        events.append(event)
    return events
