"""Stored 8-bit images: load one, find where two differ, and write the figures that show it
(a difference image over a dim copy, an image with the differing pixels marked)."""
import os

import numpy as np
from PIL import Image


def load_png(doc, rel):
    """An image a record names (absolute, or relative to the output folder) as int16 RGB, or None."""
    path = rel if os.path.isabs(rel) else os.path.join(doc.out_dir, rel)
    return np.asarray(Image.open(path).convert("RGB"), dtype=np.int16) if os.path.exists(path) else None


def relative(doc, path):
    """Image paths relative to the output folder (records may hold them absolute)."""
    return os.path.relpath(path, doc.out_dir) if os.path.isabs(path) else path


def differing(a, b):
    """Pixels where some channel differs by more than one 8-bit step. The PNGs are 8-bit, so
    this is a lower bound on a renderer's own test (a float difference above 1/255): one step
    also arises from rounding differences far below 1/255."""
    return np.any(np.abs(a - b) > 1, axis=2)


def dilate(mask, r):
    """mask grown by r pixels (a square), so single differing pixels show in a figure."""
    out = mask.copy()
    h, w = mask.shape
    for dy in range(-r, r + 1):
        for dx in range(-r, r + 1):
            out[max(dy, 0):h + min(dy, 0), max(dx, 0):w + min(dx, 0)] |= \
                mask[max(-dy, 0):h + min(-dy, 0), max(-dx, 0):w + min(-dx, 0)]
    return out


def write_difference(doc, file_name, a, b):
    """White where a and b differ, b dimly behind (a frame of reference)."""
    diff = np.where(differing(a, b)[:, :, None], 255, np.rint(0.25 * b)).astype(np.uint8)
    os.makedirs(doc.out_dir, exist_ok=True)
    Image.fromarray(diff).save(os.path.join(doc.out_dir, file_name))


def write_marked(doc, file_name, a, b, grow=2):
    """a with the pixels where it differs from b marked red, grown by `grow` pixels."""
    marked = np.where(dilate(differing(a, b), grow)[:, :, None], np.array([255, 0, 0]), a).astype(np.uint8)
    os.makedirs(doc.out_dir, exist_ok=True)
    Image.fromarray(marked).save(os.path.join(doc.out_dir, file_name))
