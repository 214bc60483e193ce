#!/usr/bin/env python3
"""tools/check-layers refuses what it must: a use of a higher layer, a loop between
folders, a folder outside the layer order, a module defined twice; and passes a tree
whose folders use only lower ones. Each case is a small tree of .f90 files."""
import pathlib
import subprocess
import sys
import tempfile

CHECK = pathlib.Path(sys.argv[1])


def tree(files):
    root = pathlib.Path(tempfile.mkdtemp(prefix="layers_"))
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def run(files):
    out = subprocess.run([sys.executable, str(CHECK), str(tree(files))], capture_output=True, text=True)
    return out.returncode, out.stdout + out.stderr


BASE = {
    "common/kinds.f90": "module kinds\nend module kinds\n",
    "c1_input/model.f90": "module model\n   use kinds, only: wp\nend module model\n",
    "c4_forces/gravity.f90": "module gravity\n   use :: model, only: model_t\n   use, intrinsic :: iso_c_binding\nend module gravity\n",
}

failures = []


def expect(name, files, code, *texts):
    rc, out = run(files)
    if rc != code or not all(t in out for t in texts):
        failures.append(f"{name}: status {rc} (expected {code}), output:\n{out}")


expect("lower uses only", BASE, 0, "no loop, no folder uses a higher one")
expect("a use of a higher layer", {**BASE, "c1_input/deck.f90": "module deck\n   use gravity\nend module deck\n"},
       1, "c1_input uses the higher layer c4_forces: c1_input/deck.f90:2 uses gravity")
expect("a loop", {**BASE, "common/strings.f90": "module strings\n   use :: model\nend module strings\n"},
       1, "the folders c1_input, common use each other round a loop", "common/strings.f90:2 uses model")
expect("a folder outside the order", {**BASE, "extras/x.f90": "module x\nend module x\n"},
       1, "folder extras is not in the layer order")
expect("a module defined twice", {**BASE, "c4_forces/model.f90": "module model\nend module model\n"},
       1, "module model in c1_input and c4_forces")

# report Section D's analog, a side branch: it uses common and c1_input only, and only the
# driver (and above) uses it
ANALOG = {**BASE, "d_analog/analog_model.f90": "module analog_model\n   use model\nend module analog_model\n",
          "driver/run_case.f90": "module run_case\n   use analog_model\nend module run_case\n"}
expect("the analog's branch kept", ANALOG, 0, "no loop, no folder uses a higher one")
expect("the analog uses the simulation", {**ANALOG, "d_analog/x.f90": "module x\n   use gravity\nend module x\n"},
       1, "d_analog may use only c1_input, common, not c4_forces: d_analog/x.f90:2 uses gravity")
expect("the simulation uses the analog", {**ANALOG, "c4_forces/y.f90": "module y\n   use analog_model\nend module y\n"},
       1, "c4_forces may not use d_analog (only app, c8_modification, driver may): c4_forces/y.f90:2 uses analog_model")

for f in failures:
    print("FAILED", f)
print(f"{8 - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
