import json
def base(S=1.0, O=(0,0,0), light=None, cam=None, extra=None):
    T=lambda p:[O[0]+p[0]*S,O[1]+p[1]*S,O[2]+p[2]*S]
    objs=[{"type":"plane","name":"ground","size":10*S,"transform":{"translate":T([0,0,0])}},
          {"type":"sphere","name":"ball","radius":1*S,"detail":3,"transform":{"translate":T([0,2,0])}},
          {"type":"box","name":"crate","size":1*S,"transform":{"translate":T([2,0.5,1]),"rotate":[0,30,0]}}]
    if extra: objs+=extra(T,S)
    l=light(T,S) if light else {"type":"point","position":T([0.5,5,0.3])}
    c=cam(T,S) if cam else {"eye":T([0,6,11]),"target":T([0,1,0]),"fov":45,"width":320,"height":240}
    d={"objects":objs,"camera":c}
    if isinstance(l,list): d["lights"]=l
    else: d["light"]=l
    return d
sc={}
for S in [1e-3,1.0,1e4]:
    for O in [0,1e5,1e6,1e7]:
        sc[f"pt_S{S:g}_O{O:g}"]=base(S,(O,O*0.5,-O))
sc["pt_inside"]=base(light=lambda T,S:{"type":"point","position":T([0,2,0])})
sc["pt_onplane"]=base(light=lambda T,S:{"type":"point","position":T([-1,0,-1])})
sc["pt_onplane_center"]=base(light=lambda T,S:{"type":"point","position":T([0,0,0])})
sc["pt_close"]=base(light=lambda T,S:{"type":"point","position":T([0,3+1e-4,0])})
sc["pt_close_box"]=base(light=lambda T,S:{"type":"point","position":T([2,1+1e-4,1])})
sc["pt_on_sphere_vertex"]=base(light=lambda T,S:{"type":"point","position":T([0,3,0])})
sc["spot_close"]=base(light=lambda T,S:{"type":"spot","position":T([0,3+1e-4,0]),"target":T([0,0,0]),"fov":90})
sc["spot_pos_eq_target"]=base(light=lambda T,S:{"type":"spot","position":T([0,5,0]),"target":T([0,5,0]),"fov":60})
sc["dir_pos_eq_target"]=base(light=lambda T,S:{"type":"directional","position":T([0,5,0]),"target":T([0,5,0])})
sc["dir_parallel"]=base(light=lambda T,S:{"type":"directional","direction":[1,0,0]})
sc["dir_parallel_neg"]=base(light=lambda T,S:{"type":"directional","direction":[-1,0,-1e-9]})
sc["dir_down_exact"]=base(light=lambda T,S:{"type":"directional","direction":[0,-1,0]})
sc["spot_on_plane_parallel"]=base(light=lambda T,S:{"type":"spot","position":T([-6,0,0]),"target":T([0,0,0]),"fov":60})
# camera inside the shadow volume (under the ball, looking up/down)
sc["cam_in_shadow_pt"]=base(cam=lambda T,S:{"eye":T([0.-0.1,1.0,-0.05]),"target":T([3,0,3]),"fov":60,"width":320,"height":240})
sc["cam_in_shadow_spot"]=base(light=lambda T,S:{"type":"spot","position":T([0,8,0]),"target":T([0,0,0]),"fov":60},
                              cam=lambda T,S:{"eye":T([0,0.5,0.1]),"target":T([3,0,3]),"fov":60,"width":320,"height":240})
sc["cam_in_shadow_dir"]=base(light=lambda T,S:{"type":"directional","direction":[0,-1,0]},
                              cam=lambda T,S:{"eye":T([0,0.5,0.1]),"target":T([3,0,3]),"fov":60,"width":320,"height":240})
sc["cam_at_light_pt"]=base(cam=lambda T,S:{"eye":T([0.5,5,0.3]),"target":T([0,0,0]),"fov":60,"width":320,"height":240})
# several lights
sc["multi_same_pos"]=base(light=lambda T,S:[{"type":"point","position":T([0.5,5,0.3]),"intensity":0.5},{"type":"point","position":T([0.5,5,0.3]),"intensity":0.5}])
sc["multi16"]=base(light=lambda T,S:[({"type":"point","position":T([i-8,3+0.1*i,1])} if i%3==0 else {"type":"spot","position":T([i-8,6,4]),"target":T([0,0,0]),"fov":50} if i%3==1 else {"type":"directional","direction":[0.1*i-0.8,-1,0.2]}) for i in range(16)])
sc["multi_inside_onplane"]=base(light=lambda T,S:[{"type":"point","position":T([0,2,0])},{"type":"point","position":T([-1,0,-1])},{"type":"directional","direction":[1,0,0]}])
sc["multi_far_tiny"]=base(1e-3,(1e7,1e7,1e7),light=lambda T,S:[{"type":"point","position":T([0.5,5,0.3])},{"type":"spot","position":T([3,6,3]),"target":T([0,0,0]),"fov":40}])
sc["multi_far_huge"]=base(1e4,(1e7,0,0),light=lambda T,S:[{"type":"point","position":T([0.5,5,0.3])},{"type":"directional","direction":[0.3,-1,0.2]}])
# point light exactly on cube-face diagonal of an object
sc["pt_diag"]=base(light=lambda T,S:{"type":"point","position":T([0,2,3])},extra=lambda T,S:[{"type":"box","name":"diag","size":0.5*S,"transform":{"translate":T([1,3,4])}}])
# point light with given near/far cutting
sc["pt_nearfar"]=base(light=lambda T,S:{"type":"point","position":T([0.5,5,0.3]),"near":2.5,"far":3.0})
sc["pt_hugefar"]=base(light=lambda T,S:{"type":"point","position":T([0.5,5,0.3]),"near":1e-9,"far":1e12})
for k,v in sc.items(): json.dump(v,open(k+".json","w"),indent=1)
print(len(sc))
