import shadowvol as sv, numpy as np
np.random.seed(1)
A = np.random.rand(10, 6); Vs = A[:, ::2]; F = np.array([[0, 1, 2], [3, 4, 5]])
sv.export(Vs, F, 'k/s1.obj'); sv.export(np.ascontiguousarray(Vs), F, 'k/s2.obj')
B = (np.arange(36).reshape(6, 6) % 10)[:, ::2]
sv.export(np.random.rand(10, 3), B, 'k/s3.obj'); 
print(open('k/s1.obj').read() == open('k/s2.obj').read())
Vt = np.random.rand(3, 10).T   # F-order
sv.export(Vt, F, 'k/s4.obj'); sv.export(np.ascontiguousarray(Vt), F, 'k/s5.obj'); print(open('k/s4.obj').read() == open('k/s5.obj').read())
Vr = np.random.rand(10, 3)[::-1]; sv.export(Vr, F, 'k/s6.obj'); sv.export(np.ascontiguousarray(Vr), F, 'k/s7.obj'); print(open('k/s6.obj').read() == open('k/s7.obj').read())
Fr = F[::-1]; sv.export(Vr, Fr, 'k/s8.obj'); sv.export(np.ascontiguousarray(Vr), np.ascontiguousarray(Fr), 'k/s9.obj'); print(open('k/s8.obj').read() == open('k/s9.obj').read())
Fb = F.astype('>i4'); sv.export(Vr, Fb, 'k/s10.obj'); print(open('k/s10.obj').read() == open('k/s7.obj').read())
