"""vobench: visibility orderings of meshes, judged by the z-buffer oracle.

    import vobench
    scene = vobench.generate("helix", cells=2000)
    cam = vobench.views(scene, 14, 256, 256)[0]
    ids = vobench.order(scene, cam, "sxmpvo")         # numpy int32, back to front
    vobench.check(scene, cam, ids)["violating_pixels"]  # 0

The compiled module (_vobench) links libvobench.so: the same orderers, datasets, view
sets and oracle as the vobench program. Bad input raises vobench.InputError, a
ValueError whose message is the one line the program prints.
"""
from ._vobench import (Camera, InputError, Scene, algorithms, cell_mesh, check, datasets, generate,
                       load, order, triangle_soup, views)

__all__ = ["Camera", "InputError", "Scene", "algorithms", "cell_mesh", "check", "datasets",
           "generate", "load", "order", "triangle_soup", "views"]
