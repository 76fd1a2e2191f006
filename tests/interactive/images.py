"""Images for the interactive tests, with ffmpeg (installed by scripts/deps.sh) as the decoder so
that the tests need nothing beyond numpy: PNG files and bytes to arrays, and the comparisons."""
import subprocess

import numpy as np


def decode(png, width=None, height=None):
    """PNG (a path, or the bytes) -> H x W x 3 uint8 array (RGB)."""
    source = png if isinstance(png, str) else "pipe:0"
    probe = subprocess.run(
        ["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
         "stream=width,height", "-of", "csv=p=0", "-f", "png_pipe", source],
        input=None if isinstance(png, str) else png, capture_output=True, check=True)
    w, h = (int(v) for v in probe.stdout.decode().strip().split(",")[:2])
    raw = subprocess.run(
        ["ffmpeg", "-v", "error", "-f", "png_pipe", "-i", source, "-f", "rawvideo",
         "-pix_fmt", "rgb24", "pipe:1"],
        input=None if isinstance(png, str) else png, capture_output=True, check=True).stdout
    return np.frombuffer(raw, np.uint8).reshape(h, w, 3)


def decode_sequence(pattern, count, width, height):
    """PNG files named by an ffmpeg pattern ("dir/frame_%05d.png", numbered from 1), in one ffmpeg
    call -> list of H x W x 3 uint8 arrays (RGB)."""
    raw = subprocess.run(
        ["ffmpeg", "-v", "error", "-f", "image2", "-start_number", "1", "-i", pattern,
         "-frames:v", str(count), "-f", "rawvideo", "-pix_fmt", "rgb24", "pipe:1"],
        capture_output=True, check=True).stdout
    frames = np.frombuffer(raw, np.uint8).reshape(-1, height, width, 3)
    assert len(frames) == count, f"decoded {len(frames)} of {count} frames"
    return list(frames)


def difference(a, b):
    """The mean absolute difference of two images of one size, per channel value."""
    assert a.shape == b.shape, f"sizes differ: {a.shape} vs {b.shape}"
    return float(np.mean(np.abs(a.astype(np.int16) - b.astype(np.int16))))


def closest(image, frames):
    """The index of the frame in `frames` most like `image`, and the differences to all."""
    d = [difference(image, f) for f in frames]
    return int(np.argmin(d)), d
