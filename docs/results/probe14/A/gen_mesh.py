#!/usr/bin/env python3
# Hostile mesh headers / counts for probe14/A (writes m/). Run in /tmp/probe14/A.
import struct, os, json, base64
os.makedirs('m', exist_ok=True)
def w(name, data):
    open('m/' + name, 'wb').write(data if isinstance(data, bytes) else data.encode())
tri = struct.pack('<12f', 0,0,1, 0,0,0, 1,0,0, 0,1,0) + b'\0\0'
# binary STL counts
w('stl_count_ffffffff.stl', b'\0'*80 + struct.pack('<I', 0xffffffff) + tri)
w('stl_count_wrap4.stl', b'\0'*80 + struct.pack('<I', 85899346) + b'\0'*4)      # 84+50N wraps to 88 in 32 bits
w('stl_count_wrap_tri.stl', b'\0'*80 + struct.pack('<I', 85899346+1) + tri + b'\0'*4)  # wraps to 138
w('stl_count_80000000.stl', b'\0'*80 + struct.pack('<I', 0x80000000) + tri)
w('stl_count_0_withdata.stl', b'\0'*80 + struct.pack('<I', 0) + tri)
w('stl_solid_binary.stl', b'solid x' + b'\0'*73 + struct.pack('<I', 1) + tri)
# PLY
def plyb(nv, nf, body, fmt='binary_little_endian', vtype='float', ltype='uchar', itype='int'):
    h = f"ply\nformat {fmt} 1.0\nelement vertex {nv}\nproperty {vtype} x\nproperty {vtype} y\nproperty {vtype} z\nelement face {nf}\nproperty list {ltype} {itype} vertex_indices\nend_header\n"
    return h.encode() + body
V3 = struct.pack('<9f', 0,0,0, 1,0,0, 0,1,0)
w('ply_v_2e64.ply', plyb('18446744073709551615', 1, V3 + struct.pack('<B3i', 3, 0, 1, 2)))
w('ply_v_2e64p1.ply', plyb('18446744073709551616', 1, V3 + struct.pack('<B3i', 3, 0, 1, 2)))
w('ply_v_4e9.ply', plyb(4000000000, 1, V3 + struct.pack('<B3i', 3, 0, 1, 2)))
w('ply_v_neg.ply', plyb(-1, 1, V3 + struct.pack('<B3i', 3, 0, 1, 2)))
w('ply_f_2e9.ply', plyb(3, 2000000000, V3 + struct.pack('<B3i', 3, 0, 1, 2)))
w('ply_f_uint_list_4e9.ply', plyb(3, 1, V3 + struct.pack('<I3i', 4000000000, 0, 1, 2), ltype='uint'))
w('ply_f_int_list_neg.ply', plyb(3, 1, V3 + struct.pack('<i3i', -5, 0, 1, 2), ltype='int'))
w('ply_f_uint_list_2e9.ply', plyb(3, 1, V3 + struct.pack('<I3i', 0x7fffffff, 0, 1, 2), ltype='uint'))
w('ply_f_idx_neg.ply', plyb(3, 1, V3 + struct.pack('<B3i', 3, 0, 1, -2147483648)))
w('ply_f_idx_uint_big.ply', plyb(3, 1, V3 + struct.pack('<B3I', 3, 0, 1, 0xffffffff), itype='uint'))
w('ply_ascii_f_2e9.ply', "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n")
w('ply_ascii_list_big.ply', "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n")
# many extra elements / properties
w('ply_many_props.ply', "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + ''.join(f"property float p{i}\n" for i in range(200000)) + "property float x\nproperty float y\nproperty float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n")
w('ply_other_elem_huge.ply', "ply\nformat binary_little_endian 1.0\nelement junk 4000000000\nproperty double a\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n")
w('ply_other_elem_list.ply', plyb(3,1,V3 + struct.pack('<B3i', 3, 0, 1, 2)).replace(b'end_header\n', b'element junk 1\nproperty list uint double a\nend_header\n') + struct.pack('<I', 0xfffffff0))
# OFF
w('off_huge.off', "OFF\n4000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
w('off_huge_f.off', "OFF\n3 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
w('off_2e64.off', "OFF\n18446744073709551617 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
w('off_face_n_huge.off', "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n")
w('off_face_n_2e9.off', "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2147483647 0 1 2\n")
w('off_neg.off', "OFF\n-3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
w('off_nv_exact_many_short.off', "OFF\n300000000 1 0\n" + "0 0 0\n"*3)
# OBJ
w('obj_idx_min.obj', "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9223372036854775808\n")
w('obj_idx_max.obj', "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9223372036854775807\n")
w('obj_idx_2e64.obj', "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 18446744073709551619\n")
w('obj_idx_int_wrap.obj', "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967299\n")
w('obj_idx_neg_wrap.obj', "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4294967295\n")
w('obj_long_face.obj', "v 0 0 0\nv 1 0 0\nv 0 1 0\nf " + "1 2 3 " * 2000000 + "\n")
w('obj_long_line.obj', "v 0 0 0\nv 1 0 0\nv 0 1 0\n#" + "x"*50000000 + "\nf 1 2 3\n")
# glTF with huge accessor count
def gltf(count, byteLength, extra=None):
    buf = struct.pack('<9f', 0,0,0, 1,0,0, 0,1,0)
    g = {"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "scene": 0, "nodes": [{"mesh": 0}],
         "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
         "buffers": [{"byteLength": byteLength, "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
         "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": byteLength}],
         "accessors": [{"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]}]}
    return json.dumps(g)
w('gltf_count_huge.gltf', gltf(4294967295, 36))
w('gltf_count_wrap.gltf', gltf(357913942, 36))  # 12*count wraps 32 bits to 8
w('gltf_bytelen_huge.gltf', gltf(3, 18446744073709551615))
