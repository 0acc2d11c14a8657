import json
exec(open('gen.py').read().split('sc={}')[0])
sc={}
for S in [1e-3,1e4]:
    for O in [1e5,1e7]:
        sc[f"spot_S{S:g}_O{O:g}"]=base(S,(O,-O,O*0.3),light=lambda T,S:{"type":"spot","position":T([3,9,2]),"target":T([-0.3,0,-0.2]),"fov":55})
        sc[f"dir_S{S:g}_O{O:g}"]=base(S,(O,-O,O*0.3),light=lambda T,S:{"type":"directional","direction":[-0.3,-1,-0.2]})
        sc[f"dirgraze_S{S:g}_O{O:g}"]=base(S,(O,-O,O*0.3),light=lambda T,S:{"type":"directional","direction":[-1,-0.02,-0.3]})
for k,v in sc.items(): json.dump(v,open(k+".json","w"),indent=1)
print(list(sc))
