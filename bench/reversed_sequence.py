#!/usr/bin/env python3
"""Makes a sequence that plays a TUM-layout sequence backwards from one of its frames.

usage: reversed_sequence.py SRC_DIR OUT_DIR --from N [--camera CAMERA_YAML]

Frames N, N-1, ..., 0 of SRC_DIR (by rgb.txt order) under new, evenly spaced timestamps (the
source's mean frame period), each with its nearest depth image and nearest ground-truth pose, the
lists naming the source images by absolute path. The ground truth keeps the source's frame (a
Bonn sequence's marker poses stay marker poses: keep "rgbd_bonn" in OUT_DIR's name, so that
segslam converts them as it does the source's). Listed images that are absent are left out.

Played backwards, a rolling-shutter camera reads its last row first: with --camera (the source's
camera settings as segslam writes them, e.g. `segslam check` into its output folder) OUT_DIR gets
that camera.yaml with the readout's sign turned.

A camera played backwards still moves as a camera can, and the scene's people walk backwards: a
sequence whose people walk in at its end becomes one that starts among people, which is what the
start-among-people benches need from the few real sequences here.
"""
import argparse
import bisect
import os
import re
import sys


def rows(path):
    return [line.split() for line in open(path) if line.split() and not line.startswith('#')]


def nearest(stamps, t):
    i = bisect.bisect_left(stamps, t)
    return min((j for j in (i - 1, i) if 0 <= j < len(stamps)), key=lambda j: abs(stamps[j] - t))


def write_reversed_camera(camera_yaml, out):
    readout = re.compile(r'^(\s*rolling_shutter_readout:\s*)(\S+)\s*$', re.M)
    text = open(camera_yaml).read()
    text = readout.sub(lambda m: m.group(1) + repr(-float(m.group(2))), text)
    with open(os.path.join(out, 'camera.yaml'), 'w') as f:
        f.write(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('src')
    parser.add_argument('out')
    parser.add_argument('--from', dest='first', type=int, required=True,
                        help='rgb.txt index of the frame played first')
    parser.add_argument('--camera', help="the source's camera settings (segslam camera.yaml)")
    args = parser.parse_args()
    src = os.path.abspath(args.src)
    rgb = rows(os.path.join(src, 'rgb.txt'))
    depth = [r for r in rows(os.path.join(src, 'depth.txt'))
             if os.path.isfile(os.path.join(src, r[1]))]
    truth = rows(os.path.join(src, 'groundtruth.txt'))
    if not 0 < args.first < len(rgb):
        sys.exit('error: --from must be in 1..%d for %s' % (len(rgb) - 1, src))
    depth_stamps = [float(r[0]) for r in depth]
    truth_stamps = [float(r[0]) for r in truth]
    t0 = float(rgb[0][0])
    period = (float(rgb[-1][0]) - t0) / (len(rgb) - 1)
    os.makedirs(args.out, exist_ok=True)
    if args.camera:
        write_reversed_camera(args.camera, args.out)
    with open(os.path.join(args.out, 'rgb.txt'), 'w') as fr, \
         open(os.path.join(args.out, 'depth.txt'), 'w') as fd, \
         open(os.path.join(args.out, 'groundtruth.txt'), 'w') as fg:
        fr.write('# %s played backwards from frame %d\n' % (src, args.first))
        fd.write('# %s played backwards from frame %d\n' % (src, args.first))
        fg.write('# %s played backwards from frame %d\n' % (src, args.first))
        for k, i in enumerate(range(args.first, -1, -1)):
            t_src = float(rgb[i][0])
            t = '%.6f' % (t0 + k * period)
            d = depth[nearest(depth_stamps, t_src)][1]
            fr.write('%s %s\n' % (t, os.path.join(src, rgb[i][1])))
            fd.write('%s %s\n' % (t, os.path.join(src, d)))
            fg.write('%s %s\n' % (t, ' '.join(truth[nearest(truth_stamps, t_src)][1:])))
    print('%d frames, %s backwards from frame %d, in %s' % (args.first + 1, src, args.first,
                                                            args.out))


if __name__ == '__main__':
    main()
