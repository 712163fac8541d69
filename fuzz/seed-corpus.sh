#!/usr/bin/env bash
# Build the seed corpora from the real files and simulated scans (written in
# every format), trimmed so each seed stays small.
set -euo pipefail
cd "$(dirname "$0")"
REAL=../tests/data/real
rm -rf corpus && mkdir -p corpus/{ply,pcd,kitti,poses,describe,json,las,e57}
cargo run --quiet --release --manifest-path ../Cargo.toml --example write_corpus -- corpus
cp $REAL/kitti00/poses.txt corpus/poses/kitti.txt
printf 'name,x,y,z\na.ply,1,2,3\n' > corpus/poses/csv.txt
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0.7071068 0.7071068\n' > corpus/poses/tum.txt
head -c 4096 $REAL/pcl_room/room_scan1.pcd > corpus/pcd/real_compressed_head.pcd
head -c 8192 $REAL/velodyne_pair/251370668.pcd > corpus/pcd/real_binary_head.pcd
head -c 8192 $REAL/ouster_os0_sequence/scan_000.bin > corpus/kitti/ouster_head.bin
# LAS/LAZ/E57 written by laspy and pye57 (tests/data/survey/make_survey.py).
cp ../tests/data/survey/{las12_fmt0,las12_fmt3,las14_fmt6}.las ../tests/data/survey/laz1*.laz corpus/las/
cp ../tests/data/survey/{survey,single}.e57 corpus/e57/
