"""numpy views of the C genome structs (neat.h's neat_node and neat_conn): the layouts are checked in the C++."""
import numpy as np

#: neat_node: uint32 id, uint8 type (0 bias, 1 input, 2 output, 3 hidden), 8 bytes
NODE = np.dtype({"names": ["id", "type"], "formats": ["<u4", "u1"], "offsets": [0, 4], "itemsize": 8})
#: neat_conn: uint32 in, uint32 out, float64 weight, uint32 innov, uint8 enabled, 24 bytes
CONN = np.dtype(
    {
        "names": ["in", "out", "weight", "innov", "enabled"],
        "formats": ["<u4", "<u4", "<f8", "<u4", "u1"],
        "offsets": [0, 4, 8, 16, 20],
        "itemsize": 24,
    }
)
