"""layout.json, typed: what a generated model's slots are, written by the generator and read
by the runtime through the same types.

The file keeps its plain JSON form (names, units, docs of every coordinate, parameter and
function slot); reading it rebuilds the typed :class:`~jointplay.robot.structure.Structure`,
:class:`~jointplay.robot.structure.Coordinate` and
:class:`~jointplay.robot.structure.Parameter` lists from the structure and checks that the
file says the same, so a hand-edited or stale layout is refused rather than misread.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from jointplay.common.errors import GeneratedCodeError
from jointplay.robot.structure import (
    Coordinate,
    Parameter,
    Structure,
    coordinate_layout,
    parameter_layout,
)


@dataclass(frozen=True)
class Slot:
    """One input or output of a generated function: name, shape, unit, and what it holds."""

    name: str
    shape: tuple[int, int]
    unit: str
    doc: str
    entries: tuple[str, ...] = ()  # the name of each entry, where entries have names
    matrix: bool = False

    def as_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"name": self.name, "shape": list(self.shape), "unit": self.unit,
                               "doc": self.doc}
        if self.matrix:
            out["matrix"] = True
        if self.entries:
            out["entries"] = list(self.entries)
        return out

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Slot:
        rows, cols = data["shape"]
        return cls(name=str(data["name"]), shape=(int(rows), int(cols)), unit=str(data["unit"]),
                   doc=str(data["doc"]), entries=tuple(data.get("entries", ())),
                   matrix=bool(data.get("matrix", False)))


@dataclass(frozen=True)
class FunctionSlots:
    """A generated function's slots, plus what the generator says about it."""

    inputs: tuple[Slot, ...]
    outputs: tuple[Slot, ...]
    jacobian: str | None = None  # the name of its generated Jacobian, if any
    newton_iterations: int | None = None  # fixed Newton count of an implicit step

    def as_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"inputs": [s.as_dict() for s in self.inputs],
                               "outputs": [s.as_dict() for s in self.outputs]}
        if self.jacobian is not None:
            out["jacobian"] = self.jacobian
        if self.newton_iterations is not None:
            out["newton_iterations"] = self.newton_iterations
        return out

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> FunctionSlots:
        return cls(inputs=tuple(Slot.from_dict(s) for s in data["inputs"]),
                   outputs=tuple(Slot.from_dict(s) for s in data["outputs"]),
                   jacobian=data.get("jacobian"), newton_iterations=data.get("newton_iterations"))


@dataclass(frozen=True)
class Layout:
    """What a generated model is: its structure, coordinates, parameters and function slots."""

    name: str
    provenance: Mapping[str, str]
    structure: Structure
    coordinates: tuple[Coordinate, ...]
    parameters: tuple[Parameter, ...]
    torque_joints: tuple[int, ...]
    functions: Mapping[str, FunctionSlots] = field(default_factory=dict)
    # Functions of the deferred library (compiled on first use); none in a model generated
    # before there was one, whose every function is in model.c.
    deferred: tuple[str, ...] = ()

    @property
    def clearance_joints(self) -> tuple[int, ...]:
        return self.structure.clearance_joints

    @property
    def coordinate_names(self) -> list[str]:
        return [c.name for c in self.coordinates]

    @property
    def parameter_names(self) -> list[str]:
        return [p.name for p in self.parameters]

    @property
    def input_hash(self) -> str:
        return str(self.provenance["input_hash"])

    def parameter_slot(self, owner: str, index: int | None, attribute: str) -> int:
        """The slot of a parameter in the vector, found by what it is, not by its name."""
        for slot, prm in enumerate(self.parameters):
            if (prm.owner, prm.index, prm.attribute) == (owner, index, attribute):
                return slot
        raise KeyError(f"this model has no parameter {attribute!r} of {owner} {index or ''}")

    def as_dict(self) -> dict[str, Any]:
        """The JSON form written to layout.json."""
        return {"name": self.name, "provenance": dict(self.provenance),
                "structure": self.structure.as_dict(),
                "coordinates": [c.as_dict() for c in self.coordinates],
                "parameters": [p.as_dict() for p in self.parameters],
                "torque_joints": list(self.torque_joints),
                "clearance_joints": list(self.clearance_joints),
                "functions": {k: f.as_dict() for k, f in self.functions.items()},
                **({"deferred": list(self.deferred)} if self.deferred else {})}

    @classmethod
    def from_dict(cls, data: Any, source: str = "layout.json") -> Layout:
        """Read layout.json's form, or raise :class:`GeneratedCodeError` saying what to do."""
        def refuse(what: str) -> GeneratedCodeError:
            return GeneratedCodeError(f"{source} {what}; regenerate it with `jointplay derive`")

        if not isinstance(data, dict):
            raise refuse("is not a layout (a JSON object is expected)")
        for key, kind in _KEYS.items():
            if not isinstance(data.get(key), kind):
                raise refuse(f"has no valid {key!r} entry")
        deferred = data.get("deferred", [])
        if not isinstance(deferred, list) or not all(isinstance(d, str) for d in deferred) \
                or (deferred and not isinstance(data["provenance"].get("deferred_code_sha256"),
                                                str)):
            raise refuse("has a malformed 'deferred' entry")
        try:
            structure = Structure.from_dict(data["structure"])
            functions = {k: FunctionSlots.from_dict(f) for k, f in data["functions"].items()}
        except (ValueError, KeyError, TypeError) as err:
            raise refuse(f"has a malformed structure or function slots ({err})") from None
        coordinates = tuple(coordinate_layout(structure))
        parameters = tuple(parameter_layout(structure))
        if [c.as_dict() for c in coordinates] != data["coordinates"] \
                or [p.as_dict() for p in parameters] != data["parameters"] \
                or list(structure.clearance_joints) != data["clearance_joints"] \
                or not isinstance(data["provenance"].get("input_hash"), str):
            raise refuse("has coordinates, parameters or provenance that do not match its "
                         "structure")
        return cls(name=data["name"], provenance=data["provenance"], structure=structure,
                   coordinates=coordinates, parameters=parameters,
                   torque_joints=tuple(data["torque_joints"]), functions=functions,
                   deferred=tuple(deferred))


_KEYS: dict[str, type] = {"name": str, "structure": dict, "coordinates": list,
                          "parameters": list, "torque_joints": list, "clearance_joints": list,
                          "functions": dict, "provenance": dict}
