#!/usr/bin/python3
"""Independent reader of a results file (.res, XRF) for tests/output/results_file_test.cpp.

Parses the file with Python's xml.etree (no OpenMSS code) and prints one line per value:
    <entity name>\t<component name>\t<data block name>\t<step index>\t<value as repr(float)>
for every component of every step of every <Data> block, in file order. The C++ test compares
these with its own reader, value by value. Exit status 1 with a message when the file is not
an XRF results file or a step does not hold one value per component.
"""
import sys
import xml.etree.ElementTree as ET

NS = "{http://www.mscsoftware.com/:xrf10}"


def main(path):
    root = ET.parse(path).getroot()
    if root.tag != NS + "Results":
        sys.exit("not an XRF results file: root element " + root.tag)
    components = []  # (id, entity name, component name)
    for entity in root.iter(NS + "Entity"):
        for comp in entity.iter(NS + "Component"):
            components.append((int(comp.get("id")), entity.get("name"), comp.get("name")))
    count = max(c[0] for c in components)
    out = []
    for data in root.iter(NS + "Data"):
        for index, step in enumerate(data.iter(NS + "Step")):
            values = [float(v) for v in step.text.split()]
            if len(values) != count:
                sys.exit("%s step %d holds %d values for %d components"
                         % (data.get("name"), index, len(values), count))
            for cid, entity, name in components:
                out.append("%s\t%s\t%s\t%d\t%r" % (entity, name, data.get("name"), index,
                                                   values[cid - 1]))
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main(sys.argv[1])
