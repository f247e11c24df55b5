"""Reading XML results files (.res, ADAMS's "XRF" format, namespace
http://www.mscsoftware.com/:xrf10), written by ADAMS/Solver or by OpenMSS, in pure Python.

The StepMap lists entities (parts, joints, requests, ...) and their components, each with an
id; every <Step> of a <Data> block is a whitespace-separated list of numbers in id order, value
k belonging to the component with id k (id 1 is TIME). docs/output-files.md and
docs/python.md describe the layout. The file is read with xml.etree's iterparse, element by
element, so a long run's file is never held whole as a tree."""

import xml.etree.ElementTree as ET

import numpy as np
import pandas as pd


class ResultsFileError(ValueError):
    """A malformed results file."""


class Component:
    __slots__ = ("name", "id", "units", "plot_label")

    def __init__(self, name, id, units="", plot_label=""):
        self.name = name
        self.id = id
        self.units = units
        self.plot_label = plot_label

    def __repr__(self):
        return f"Component({self.name!r}, id={self.id}, units={self.units!r})"


class Entity:
    """A result set of the StepMap: ``name``, ``entity`` (the object's name), ``type`` (the
    entType: Part, Joint, Request, ...), ``object_id`` (its id in the data set, None when
    absent) and ``components`` in file order."""

    __slots__ = ("name", "entity", "type", "object_id", "components")

    def __init__(self, name, entity, type, object_id):
        self.name = name
        self.entity = entity
        self.type = type
        self.object_id = object_id
        self.components = []

    def __repr__(self):
        return (f"Entity({self.name!r}, type={self.type!r}, object_id={self.object_id}, "
                f"{len(self.components)} components)")


class ResultsFile:
    """The contents of a .res: ``title``, ``units`` (dict of the Units element), ``status``
    (TerminationStatus runStatus, "" when absent: a run cut off), ``entities`` (name ->
    Entity), ``steps`` (list of (data name, step type) per kept step), ``times`` and
    ``values`` (array [step, id - 1]), and DataFrames per entity and per request."""

    def __init__(self, path, title, units, status, entities, steps, values):
        self.path = path
        self.title = title
        self.units = units
        self.status = status
        self.entities = entities
        self.steps = steps
        self.values = values
        self.times = values[:, 0] if values.size else np.zeros(0)
        self._frames = {}

    def entity(self, name):
        """The DataFrame of one entity (by name), indexed by time, a column per component."""
        if name not in self._frames:
            if name not in self.entities:
                raise KeyError(f"{self.path}: no entity {name!r}")
            e = self.entities[name]
            cols = [c.id - 1 for c in e.components]
            data = np.full((len(self.times), len(cols)), np.nan)
            for j, col in enumerate(cols):
                if col < self.values.shape[1]:
                    data[:, j] = self.values[:, col]
            frame = pd.DataFrame(data, index=pd.Index(self.times, name="time"),
                                 columns=[c.name for c in e.components])
            frame.attrs.update(entity=e.name, type=e.type, object_id=e.object_id,
                               units={c.name: c.units for c in e.components})
            self._frames[name] = frame
        return self._frames[name]

    def request_entity(self, request_id):
        """The Entity of REQUEST/id: entType Request with that objectId."""
        for e in self.entities.values():
            if e.type == "Request" and e.object_id == request_id:
                return e
        raise KeyError(f"{self.path}: no REQUEST/{request_id}")

    @property
    def requests(self):
        """id -> DataFrame of every request entity with an objectId."""
        return {e.object_id: self.entity(e.name) for e in self.entities.values()
                if e.type == "Request" and e.object_id is not None}

    def request(self, request_id):
        return self.entity(self.request_entity(request_id).name)

    def __repr__(self):
        return (f"ResultsFile({self.path!r}: {len(self.entities)} entities, "
                f"{len(self.steps)} steps)")


def _local(tag):
    return tag.rsplit("}", 1)[-1]


def _int_or_none(text):
    try:
        return int(text)
    except (TypeError, ValueError):
        return None


def read_res(path, include=("initialConditions", "static", "kinematic", "dynamic",
                            "transient", "quasiStatic", "quasistatic")):
    """Reads a results file. `include` names the <Step type=...> kept in the time series
    (default: every analysis step; the "input" step, the model's input values, is left out).
    Of consecutive kept steps with the same time the last is kept, as for the .req."""
    path = str(path)
    entities, steps, rows = {}, [], []
    title, units, status = "", {}, ""
    current, data_name, width = None, "", 0
    try:
        for event, elem in ET.iterparse(path, events=("start", "end")):
            tag = _local(elem.tag)
            if event == "start":
                if tag == "Entity":
                    a = elem.attrib
                    current = Entity(a.get("name", ""), a.get("entity", a.get("name", "")),
                                     a.get("entType", ""), _int_or_none(a.get("objectId")))
                    entities[current.name] = current
                elif tag == "Data":
                    data_name = elem.attrib.get("name", "")
                continue
            if tag == "Component" and current is not None:
                a = elem.attrib
                cid = _int_or_none(a.get("id"))
                if cid is None or cid < 1:
                    raise ResultsFileError(f"{path}: component {a.get('name')!r} of "
                                           f"{current.name!r} has no valid id")
                current.components.append(Component(a.get("name", ""), cid,
                                                    a.get("unitsValue", ""),
                                                    a.get("plotLabel", "")))
                width = max(width, cid)
            elif tag == "Entity":
                current = None
            elif tag == "Step":
                kind = elem.attrib.get("type", "")
                if kind in include:
                    try:
                        numbers = [float(w) for w in (elem.text or "").split()]
                    except ValueError as e:
                        raise ResultsFileError(f"{path}: step {len(steps) + 1} of "
                                               f"{data_name!r}: {e}")
                    if not numbers:
                        raise ResultsFileError(f"{path}: an empty step in {data_name!r}")
                    if rows and rows[-1][0] == numbers[0]:
                        rows[-1], steps[-1] = numbers, (data_name, kind)
                    else:
                        rows.append(numbers)
                        steps.append((data_name, kind))
                elem.clear()  # the step's text is no longer needed
            elif tag == "ModelInfo":
                title = elem.attrib.get("title", "")
            elif tag == "Units":
                units = dict(elem.attrib)
            elif tag == "TerminationStatus":
                status = elem.attrib.get("runStatus", "")
    except ET.ParseError as e:
        raise ResultsFileError(f"{path}: not well-formed XML: {e}") from e
    width = max([width] + [len(r) for r in rows])
    values = np.full((len(rows), width), np.nan)
    for k, r in enumerate(rows):
        values[k, :len(r)] = r
    return ResultsFile(path, title, units, status, entities, steps, values)
