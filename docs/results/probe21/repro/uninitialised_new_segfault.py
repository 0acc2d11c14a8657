# An instance made by __new__ without __setstate__ (what a pickle stream without its BUILD step
# gives) is used as a valid DepthMap / Scene: garbage fields, then a segfault (exit 139).
import sys, pickle, copyreg; sys.path.insert(0, '/tmp/probe21/py'); import shadowvol as sv
# a pickle stream that only does cls.__new__(cls) (protocol 2's NEWOBJ, no BUILD / __setstate__):
data = b'\x80\x02cshadowvol\nDepthMap\nq\x00)\x81q\x01.'
d = pickle.loads(data)            # accepted: no error
print('width of the unpickled map:', d.width, flush=True)  # garbage
s = sv.Scene.__new__(sv.Scene)
print(repr(s), flush=True)        # shows another (freed) scene's data or garbage
print(repr(d), flush=True)        # segfault
