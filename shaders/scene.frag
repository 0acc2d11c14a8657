// Shading of the camera pass (docs/gpu.md "Lighting"):
//   colour = albedo * (ambient + diffuse * max(dot(N, L), 0) * lit)
// N: the flat face normal (from screen-space derivatives) turned toward the camera; L: toward the
// light (spot and point: toward its position; directional: against its direction). lit = 0
// outside the light's frustum (|x|, |y|, |z| <= w in light clip space; a point light's: between
// its near and far cubes, the largest |coordinate| of the offset from it in [near, far],
// cube_map.h), times the shadow-map visibility when shadowTaps > 0. Location 0: that colour. Location 1 (writeVisibility): the shadow test alone
// (1 = lit, PCF fraction; 1 outside the frustum; not multiplied by N.L), which the renderer binds
// to an R8 attachment only when RenderOptions::readVisibility is set. Location 2: the ambient term
// alone, albedo * ambient, which the stencil methods' camera pass keeps for the pixels their
// stencil shadows (ambient_over.frag); the renderer binds it only in that pass.
in vec3 worldPos;
in vec3 color;
uniform vec3 cameraPosition;      // world
uniform int lightType;            // LightType: 0 spot, 1 directional, 2 point
uniform vec2 lightNearFar;        // a point light's near and far (light.h)
uniform vec3 lightPosition;       // world, spot apex or point light
uniform vec3 lightDirection;      // world, unit, the way the light shines
uniform mat4 worldToLightClip;    // P_light * V_light
uniform mat4 worldToLightView;    // V_light
uniform vec4 lightDepthParams;    // reversed-Z light projection P22, P32, P23, P33
uniform float ambient;
uniform float diffuse;
uniform int shadowTaps;           // 0: no shadow test; 1: one tap; 3 or 5: PCF n x n
uniform sampler2DShadow shadowMap;  // window depth (reversed Z), compare GEQUAL, nearest
uniform samplerCubeShadow cubeShadowMap;  // a point light's (lightType 2): the same per cube face
uniform int pointShadowMap;       // a point light's shadow map: 0 the cube map, 1 dual-paraboloid (shadowMap, both maps side by side)
uniform vec2 shadowMapSize;       // texels
uniform float biasConstant;       // world units
uniform float biasSlope;          // x texel footprint x tan(angle between N and the light axis)
uniform float texelFootprint;     // world size of a texel: spot at unit depth, directional overall
uniform int writeVisibility;      // 1: evaluate the shadow test everywhere in the frustum for visibilityOut
layout(location = 0) out vec4 fragColor;
layout(location = 1) out float visibilityOut;
layout(location = 2) out vec4 ambientOut;

// Visibility in [0, 1] from the shadow map. The stored quantity is light-view depth (-z), so the
// slope that matters is the receiver's tilt against the light's view axis (not against the ray):
// tan(theta) with cos(theta) = |dot(N, lightDirection)|, clamped to 10.
float shadowVisibility(vec4 lightClip, float cosTheta) {
  float d = -(worldToLightView * vec4(worldPos, 1.0)).z;
  float footprint = lightType != 1 ? texelFootprint * d : texelFootprint;
  float c = clamp(cosTheta, 1e-4, 1.0);
  float tanTheta = min(sqrt(max(1.0 - c * c, 0.0)) / c, 10.0);
  float z = -(d - (biasConstant + biasSlope * footprint * tanTheta));
  float ref = (lightDepthParams.x * z + lightDepthParams.y) / (lightDepthParams.z * z + lightDepthParams.w);
  vec2 uv = lightClip.xy / lightClip.w * 0.5 + 0.5;
  int r = shadowTaps / 2;
  float sum = 0.0;
  for (int y = -r; y <= r; ++y)
    for (int x = -r; x <= r; ++x) sum += texture(shadowMap, vec3(uv + vec2(float(x), float(y)) / shadowMapSize, ref));
  return sum / float((2 * r + 1) * (2 * r + 1));
}

// A point light's visibility from its cube shadow map: the depth is the largest |coordinate| of
// the offset (cube_map.h), the reference as shadowVisibility's with the faces' shared projection,
// PCF taps a texel apart in the plane of the face the offset falls on.
float cubeShadowVisibility(vec3 n) {
  vec3 o = worldPos - lightPosition;
  int axis = cubeFaceOf(o) / 2;
  float d = abs(o[axis]);
  vec3 major = vec3(0.0);
  major[axis] = sign(o[axis]);
  float c = clamp(abs(dot(n, major)), 1e-4, 1.0);
  float tanTheta = min(sqrt(max(1.0 - c * c, 0.0)) / c, 10.0);
  float z = -(d - (biasConstant + biasSlope * texelFootprint * d * tanTheta));
  float ref = (lightDepthParams.x * z + lightDepthParams.y) / (lightDepthParams.z * z + lightDepthParams.w);
  vec3 t1 = vec3(0.0), t2 = vec3(0.0);
  t1[(axis + 1) % 3] = 1.0;
  t2[(axis + 2) % 3] = 1.0;
  vec3 onFace = o / d;
  float step = 2.0 / shadowMapSize.x;
  int r = shadowTaps / 2;
  float sum = 0.0;
  for (int y = -r; y <= r; ++y)
    for (int x = -r; x <= r; ++x)
      sum += texture(cubeShadowMap, vec4(onFace + (float(x) * t1 + float(y) * t2) * step, ref));
  return sum / float((2 * r + 1) * (2 * r + 1));
}

// A point light's visibility from its dual-paraboloid maps (paraboloid.glsl; shadowMap holds the
// front map left of the back one): the stored quantity is the distance along the ray, so the
// slope term uses the receiver's tilt against the ray; texelFootprint is the map's coarsest
// texel (its centre, 4 / side radians).
float paraboloidVisibility(vec3 n) {
  vec3 o = worldPos - lightPosition;
  float l = length(o);
  int h = (paraboloidToFront * vec4(o, 0.0)).z >= 0.0 ? 0 : 1;
  float c = clamp(abs(dot(n, o / max(l, 1e-30))), 1e-4, 1.0);
  float tanTheta = min(sqrt(max(1.0 - c * c, 0.0)) / c, 10.0);
  float ref = paraboloidStoredDepth(l - (biasConstant + biasSlope * texelFootprint * l * tanTheta));
  vec2 uv = paraboloidXy(paraboloidFrameOffset(o, h)) * 0.5 + 0.5;
  float halfTexel = 0.5 / shadowMapSize.y;  // keep the lookup in its own map
  uv = clamp(uv, vec2(halfTexel), vec2(1.0 - halfTexel));
  uv.x = (uv.x + float(h)) * 0.5;
  return texture(shadowMap, vec3(uv, ref));
}

void main() {
  ambientOut = vec4(color * ambient, 1.0);
  vec3 n = normalize(cross(dFdx(worldPos), dFdy(worldPos)));
  if (dot(n, cameraPosition - worldPos) < 0.0) n = -n;
  vec3 l = lightType != 1 ? normalize(lightPosition - worldPos) : -lightDirection;
  float ndl = dot(n, l);
  vec4 lc = worldToLightClip * vec4(worldPos, 1.0);
  vec3 offset = abs(worldPos - lightPosition);
  float cubeDepth = max(offset.x, max(offset.y, offset.z));
  float lit = lightType == 2 ? ((cubeDepth >= lightNearFar.x && cubeDepth <= lightNearFar.y) ? 1.0 : 0.0)
              : (lc.w > 0.0 && all(lessThanEqual(abs(lc.xyz), vec3(lc.w)))) ? 1.0 : 0.0;
  float test = 1.0;
  if (lit > 0.0 && (ndl > 0.0 || writeVisibility != 0) && shadowTaps > 0)
    test = lightType != 2          ? shadowVisibility(lc, abs(dot(n, lightDirection)))
           : pointShadowMap == 1 ? paraboloidVisibility(n)
                                 : cubeShadowVisibility(n);
  visibilityOut = test;
  if (ndl > 0.0) lit *= test;
  vec3 direct = color * diffuse * max(ndl, 0.0) * lit;
  fragColor = vec4(color * ambient + direct, 1.0);
}
