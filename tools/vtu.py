"""Read the data arrays of a VTU file written by tribos (deal.II's
binary, zlib-compressed, base64-encoded format). Standard library only;
used by tools/corner_jacobians.py and the tests."""

import base64
import re
import struct
import sys
import zlib

TYPES = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q",
         "UInt8": "B", "UInt32": "I", "UInt64": "Q"}


def read_arrays(path):
    """Binary data arrays of a zlib-compressed VTU, by name ('Points' for
    the unnamed coordinates)."""
    text = open(path).read()
    arrays = {}
    pattern = (r'<DataArray type="(\w+)"(?: Name="(\w+)")?'
               r'(?: NumberOfComponents="(\d+)")?[^>]*format="binary">'
               r'\s*(\S+)\s*</DataArray>')
    for match in re.finditer(pattern, text):
        kind, name, components, data = match.groups()
        raw = data.encode()
        n_blocks = struct.unpack("<I", base64.b64decode(raw[:8])[:4])[0]
        header_length = ((12 + 4 * n_blocks + 2) // 3) * 4
        header = base64.b64decode(raw[:header_length])
        sizes = struct.unpack("<%dI" % n_blocks, header[12:12 + 4 * n_blocks])
        body = base64.b64decode(raw[header_length:])
        decoded, position = b"", 0
        for size in sizes:
            decoded += zlib.decompress(body[position:position + size])
            position += size
        code = TYPES[kind]
        values = struct.unpack("<%d%s" % (len(decoded) // struct.calcsize(code),
                                          code), decoded)
        arrays[name or "Points"] = (values, int(components or 1))
    return arrays


def nodal_values(path, name, cell_tag=None):
    """Per distinct point of a VTU (deal.II writes each cell's points
    separately): the reference coordinates (3 values), the values of the
    point field `name` and a tag of the cells around it, cell_tag(arrays,
    cell, corners) with `corners` the cell's reference corner coordinates
    (e.g. which body the cell belongs to); points at the same place with
    different tags (the two sides of an interface) stay apart. Returns a
    list of (coordinates, values, tag)."""
    arrays = read_arrays(path)
    points = arrays["Points"][0]
    values, n_components = arrays[name]
    connectivity = arrays["connectivity"][0]
    offsets = arrays["offsets"][0]
    nodes = {}
    start = 0
    for cell, end in enumerate(offsets):
        ids = connectivity[start:end]
        corners = [points[3 * i:3 * i + 3] for i in ids]
        tag = cell_tag(arrays, cell, corners) if cell_tag else None
        for i in ids:
            key = tuple(points[3 * i + d] for d in range(3)) + (tag,)
            nodes.setdefault(
                key, values[n_components * i:n_components * (i + 1)])
        start = end
    return [(list(k[:3]), list(v), k[3]) for k, v in nodes.items()]
