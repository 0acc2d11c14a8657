import json
exec(open('gen.py').read().split('sc={}')[0])
sc={}
for S in [1e-3,1e4]:
  for O in [1e5,1e7]:
    pass
sc["pt_very_far"]=base(light=lambda T,S:{"type":"point","position":[3e5,1e6,2e5]})
sc["pt_far_1e4"]=base(light=lambda T,S:{"type":"point","position":[300,1000,200]})
sc["pt_box_corner"]=base(light=lambda T,S:{"type":"point","position":[2.5,1.0,1.5]},extra=lambda T,S:[{"type":"box","name":"axisbox","size":1,"transform":{"translate":[2,0.5,1]}}])
sc["pt_box_face"]=base(light=lambda T,S:{"type":"point","position":[-3,1.0,-3]},extra=lambda T,S:[{"type":"box","name":"axisbox","size":[1,2,1],"transform":{"translate":[-3,0,-3]}}])
sc["pt_below_ground"]=base(light=lambda T,S:{"type":"point","position":[0.3,-2,0.2]})
sc["spot_fov179"]=base(light=lambda T,S:{"type":"spot","position":[0.5,5,0.3],"direction":[0,-1,0],"fov":178.99})
sc["spot_fov001"]=base(light=lambda T,S:{"type":"spot","position":[0.5,5,0.3],"target":[0,2,0],"fov":0.01})
sc["spot_fov001_far"]=base(light=lambda T,S:{"type":"spot","position":[0,3500,0],"target":[0,2,0],"fov":0.01})
sc["cam_inside_sphere"]=base(cam=lambda T,S:{"eye":[0,2,0.2],"target":[0,0,3],"fov":90,"width":320,"height":240})
sc["dup_spheres_pt"]=base(extra=lambda T,S:[{"type":"sphere","name":"ball2","radius":1,"detail":3,"transform":{"translate":[0,2,0]}}])
sc["touching_boxes_pt"]=base(extra=lambda T,S:[{"type":"box","name":"b1","size":1,"transform":{"translate":[-2,0.5,2]}},{"type":"box","name":"b2","size":1,"transform":{"translate":[-2,1.5,2]}}])
sc["pt_up_is_axis"]=base(light=lambda T,S:{"type":"point","position":[0,6,0]})
sc["many_pts_cube_axes"]=base(light=lambda T,S:[{"type":"point","position":[0,3,0]},{"type":"point","position":[2,0.5,3]},{"type":"point","position":[2.5,0.5,1]}])
sc["spot_inside_box"]=base(light=lambda T,S:{"type":"spot","position":[2,0.5,1],"direction":[0,-1,0],"fov":90})
sc["dir_with_pos_cut"]=base(light=lambda T,S:{"type":"directional","position":[0,2,0],"direction":[0,-1,0.1]})
sc["cam_far_away"]=base(cam=lambda T,S:{"eye":[0,6e5,1.1e6],"target":[0,1,0],"fov":0.05,"width":320,"height":240})
sc["cam_far_tiny_fov_spot"]=base(light=lambda T,S:{"type":"spot","position":[3,9,2],"target":[0,0,0],"fov":40},cam=lambda T,S:{"eye":[0,6e5,1.1e6],"target":[0,1,0],"fov":0.05,"width":320,"height":240})
for k,v in sc.items(): json.dump(v,open(k+".json","w"),indent=1)
print(list(sc))
