"""Generated code is a build product with provenance: regenerate it and diff."""

from __future__ import annotations

import json

import casadi
import pytest
import sympy

from jointplay import generated, load_robot
from jointplay.common.errors import GeneratedCodeError
from jointplay.derive import emit
from jointplay.derive.codegen import write_generated
from jointplay.store.model import check_generated, read_generated

FOLDERS = generated.folders()


def test_paper_model_is_checked_in() -> None:
    assert "paper_4dof" in FOLDERS


@pytest.mark.parametrize("name", sorted(FOLDERS))
def test_regenerate_and_diff(name: str, update_generated: bool) -> None:
    folder = FOLDERS[name]
    robot = load_robot(folder / "robot.toml")
    if update_generated:
        write_generated(robot, folder)
        return
    stamped = json.loads((folder / "layout.json").read_text())["provenance"]
    installed = {"casadi": casadi.__version__, "sympy": sympy.__version__}
    differs = {k: (stamped[k], v) for k, v in installed.items() if stamped[k] != v}
    assert not differs, (
        f"generated/{name} was stamped with "
        + ", ".join(f"{k} {a}" for k, (a, _) in differs.items())
        + " but this environment has "
        + ", ".join(f"{k} {b}" for k, (_, b) in differs.items())
        + ": install the pinned versions (pip install -e .) or, after bumping the pins, "
          "regenerate with `pytest tests/test_generated.py --update-generated`")
    emitted = emit(robot)
    on_disk = (folder / "model.c").read_text()
    assert emitted.source == on_disk, (
        f"generated/{name}/model.c differs from what the generator emits now; regenerate with "
        "`pytest tests/test_generated.py --update-generated` and review the diff")
    assert emitted.deferred_source == (folder / "model_deferred.c").read_text(), (
        f"generated/{name}/model_deferred.c differs from what the generator emits now; "
        "regenerate with `pytest tests/test_generated.py --update-generated` and review the diff")
    assert json.loads((folder / "layout.json").read_text()) == json.loads(
        json.dumps(emitted.layout)), f"generated/{name}/layout.json is stale"


def test_hand_edited_source_is_refused(tmp_path) -> None:  # type: ignore[no-untyped-def]
    folder = FOLDERS["paper_4dof"]
    for f in ("model.c", "model_deferred.c", "layout.json", "robot.toml"):
        (tmp_path / f).write_text((folder / f).read_text())
    deferred = (tmp_path / "model_deferred.c").read_text()
    (tmp_path / "model_deferred.c").write_text(deferred.replace("return 0;", "return 1;", 1))
    with pytest.raises(GeneratedCodeError, match=r"model_deferred\.c was edited"):
        check_generated(tmp_path)
    (tmp_path / "model_deferred.c").write_text(deferred)
    check_generated(tmp_path)
    text = (tmp_path / "model.c").read_text()
    (tmp_path / "model.c").write_text(text.replace("input hash: ", "input hash: 0", 1)[:-1])

    with pytest.raises(GeneratedCodeError, match="input hash"):
        read_generated(tmp_path)
    (tmp_path / "model.c").write_text(text.replace("casadi_real", "double", 1))
    with pytest.raises(GeneratedCodeError, match="edited after it was generated"):
        read_generated(tmp_path)
    (tmp_path / "layout.json").unlink()
    with pytest.raises(GeneratedCodeError, match=r"layout\.json is missing"):
        read_generated(tmp_path)
