//VTK::System::Dec

//=========================================================================
// Deep screen-space radiosity gather (Mara et al. 2016, section 3.2,
// equations 3-5, with the spiral taps of section 3.4), for the surfaces of
// layers 0 and 1 of each pixel (propagation across layers, section 3.3,
// Figure 5). Writes, per output layer, (E, M / N):
//   E(X) = 2 pi / M sum_i B(Y_i) (w_i . n_X)          (eq. 4)
// over the M of the N taps that pass eq. 5. The taps are the same screen
// positions for both output layers (r_p from layer 0's depth). At a tap,
// every layer's surface Y is a candidate; a candidate passes when
// |Y - X| < r, w.n_X > epsilon and, with the n_Y test, w.n_Y < -epsilon
// (epsilon = deepCosineEpsilon absorbs the Oct16 quantisation of normals,
// so that taps on X's own plane are rejected instead of counted with a
// cosine of +-0.005). Of the passing candidates the tap uses the one with
// the larger contribution |B (w.n_X)| (the paper's supplementary shader
// does the same); a tap with no passing candidate is rejected. M = 0 gives
// E = 0. Taps outside the image are rejected. With a resolution divisor D
// (vtkDeepRadiosityPass::SetResolutionDivisor) the output is a grid D times
// coarser whose texel q gathers for the layers' texel D q: the taps and
// their sources stay those of the layers.
//
// Taps beyond the nearest ones sit at a per-pixel offset across their rings
// (deepRadialOffset), not at the rings' middle: with the same tap distances
// in every pixel, the number of taps that reach a bright neighbour (a lit
// sphere above a floor) steps with the distance to it and draws rings
// r_p / N apart around it; the offsets turn the steps into noise that the
// blur removes.
//
// With deepOuterSamples K > 0 (vtkDeepRadiosityPass::OuterSamples), K more
// taps follow the spiral's N in the ring from r_p to deepOuterScale r_p,
// tap k of them at the angle 2 pi (k + 1/2) / K + phi and at the same
// offset across its ring, and every tap accepts surfaces within
// deepOuterScale r; the confidence is then M / (N + K).
//
// With deepTapStride S > 1 (vtkDeepRadiosityPass::TemporalInterleave, while
// the temporal filter is on) receiver q takes only the taps i = deepTapPhase
// + q.x + q.y mod S of the N + K, each standing for S taps: neighbouring
// receivers take different shares, which the blur mixes, and the S frames of
// a cycle gather every tap once, which the temporal filter averages.
// SOLID_ANGLE's cap (below) is then S times 2 pi max B: a share is noisier
// than the whole gather, and clipping it at the whole gather's bound
// darkened the settled image (on the wavelet iso-surface its RMSE against
// the reference rose from 0.073 to 0.101, its mean fell by 0.02).
//
// deepEstimator (vtkDeepRadiosityPass::Estimator) chooses the sum:
//   0 ACCEPTED_TAPS: eq. 4 as printed, 2 pi / M sum B (w.n_X);
//   1 ALL_TAPS:      2 pi / N sum B (w.n_X) (rejected taps count as 0);
//   2 SOLID_ANGLE:   sum B (w.n_X) dOmega_i, dOmega_i the solid angle of
//     the surface patch that tap i stands for: its screen ring
//     2 pi h_i r_p / N pixels^2 (the spiral puts one tap per ring of width
//     r_p / N), times the world area of a pixel at Y's distance, divided by
//     |n_Y . view| (the patch is tilted away from the view; at least 0.1),
//     times (-w.n_Y) / |Y - X|^2. Its mean over the spiral's rotations is
//     the light of the whole disc, but a tap next to X (a wall meeting X's
//     surface) can stand for far more than the hemisphere; E is capped at
//     2 pi max B over the accepted taps, the bound of eq. 4, which cuts
//     such outliers without scaling down every pixel whose dOmega_i add up
//     to more than 2 pi.
//=========================================================================

in vec2 texCoord;

uniform sampler2D deepKey;         // both layers' distance and normal (vtkDeepGeometryKeyFS)
uniform sampler2D deepBounce0;     // (B, coverage) of layer 0 from level deepMinMip on
uniform sampler2D deepBounce1;     // of layer 1 (vtkDeepRadiosityBounceFS)
uniform int deepAverageFarTaps;    // taps above deepMinMip read their block's mean B
uniform int deepSamples;           // N
uniform float deepTurns;           // tau(N), Listing 3
uniform float deepRadius;          // r, world units
uniform int deepOuterSamples;      // K, taps of the outer ring
uniform float deepOuterScale;      // the outer ring's radius over r
uniform float deepMipThreshold;    // q, pixels
uniform int deepMinMip;            // Table 2's minimum MIP level
uniform int deepMaxMip;
uniform int deepNormalTest;        // the n_Y test of eq. 5
uniform float deepCosineEpsilon;
uniform float deepRotationOffset;  // radians added to phi (temporal)
uniform int deepEstimator;         // 0 accepted taps, 1 all taps, 2 solid angle
uniform ivec2 deepReceiverGrid;    // texels of the output grid
uniform int deepDivisor;           // D: output texel q gathers for layer texel D q
uniform int deepTapStride;         // S: this frame's taps are every S-th
uniform int deepTapPhase;          // the frame's first of them, 0 to S - 1
uniform float deepIrradianceLimit; // the largest half float (RGBA16F output)

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

void main()
{
  ivec2 isize = textureSize(deepKey, 0);
  vec2 size = vec2(isize);
  ivec2 receiver = min(ivec2(texCoord * vec2(deepReceiverGrid)), deepReceiverGrid - 1);
  ivec2 pixel = min(receiver * deepDivisor, isize - 1);
  vec4 key = texelFetch(deepKey, pixel, 0);
  float d0 = key.x;
  gl_FragData[0] = vec4(0.0);
  gl_FragData[1] = vec4(0.0);
  if (!(d0 > 0.0) || !(deepRadius > 0.0))
  {
    return;
  }
  vec2 center = vec2(pixel) + 0.5;
  vec3 X[2];
  vec3 nX[2];
  bool valid[2];
  for (int j = 0; j < 2; ++j)
  {
    vec2 geometry = j == 0 ? key.xy : key.zw;
    valid[j] = geometry.x > 0.0;
    X[j] = deepPositionFromDistance(center, size, max(geometry.x, 0.0));
    nX[j] = deepUnpackOct16(geometry.y);
  }
  // The layers are loops whose trip count leaves out an absent layer 1,
  // not loops over both with a test inside: a CPU renderer (Mesa llvmpipe)
  // shades 8 texels in lockstep and runs both sides of a branch for all of
  // them, but stops a loop that none of them still runs. Most receivers and
  // taps have no layer 1 (a floor, a wall facing the camera), and this takes
  // 10-20 % off the gather on llvmpipe.
  int receivers = valid[1] ? 2 : 1;
  float reach = deepOuterSamples > 0 ? deepOuterScale * deepRadius : deepRadius;
  float r2 = reach * reach;
  float rp = deepScreenRadius(deepRadius, d0, size);
  float phi = deepSpiralRotation(receiver) + deepRotationOffset;
  float offset = deepRadialOffset(phi);
  float ringWidth = rp / float(deepSamples);
  float minTexel = float(1 << deepMinMip);
  bool solidAngle = deepEstimator == DEEP_ESTIMATOR_SOLID_ANGLE;
  bool useNormals = deepNormalTest != 0 || solidAngle;
  float tapShare = float(deepTapStride); // the taps each of this frame's stands for
  float ringArea = 2.0 * deepPi * ringWidth * tapShare; // times h: the tap's screen ring
  float outerWidth = deepOuterSamples > 0 ? rp * (deepOuterScale - 1.0) / float(deepOuterSamples) : 0.0;
  float outerArea = 2.0 * deepPi * outerWidth * tapShare; // times h, as ringArea

  vec3 sum[2] = vec3[2](vec3(0.0), vec3(0.0));
  float used[2] = float[2](0.0, 0.0);
  vec3 maxB[2] = vec3[2](vec3(0.0), vec3(0.0)); // of the accepted taps
  int taps = deepSamples + deepOuterSamples;
  // This frame's share of the taps, alternating between neighbouring
  // receivers so that the blur mixes every share into each frame.
  int tapPhase = (deepTapPhase + receiver.x + receiver.y) % deepTapStride;
  for (int i = tapPhase; i < taps; i += deepTapStride)
  {
    // The tap at distance h and angle theta from the centre; one cosine and
    // sine for both kinds of tap (llvmpipe runs both sides of the branch).
    float h;
    float theta;
    float tapRingArea = ringArea; // times h: the tap's screen ring
    // Taps stay at their rings' middle (the paper's spiral) where offsets
    // would cost more than the rings: the first tap, which moved nearer
    // would read the texel that holds X, X's own surface, lighting nothing;
    // every tap where the rings are no wider than a texel of the minimum
    // MIP level (2^deepMinMip pixels, the spacing of the sources, so the
    // steps are finer than the blur); and on a reduced grid, where the
    // offsets' noise outlives the blur and the bounces lose light (on the
    // wavelet iso-surface the grid's bounced light fell to 0.39 of full
    // resolution's, against 0.50 with the grid's taps in the middle).
    if (i < deepSamples)
    {
      bool middle = i == 0 || ringWidth <= minTexel || deepDivisor > 1;
      deepSpiralTapPolar(i, middle ? 0.5 : offset, deepSamples, deepTurns, rp, phi, h, theta);
    }
    else
    {
      // The outer ring, one tap per K-th of the circle.
      int k = i - deepSamples;
      bool middle = outerWidth <= minTexel || deepDivisor > 1;
      h = rp + outerWidth * (float(k) + (middle ? 0.5 : offset));
      theta = 2.0 * deepPi * (float(k) + 0.5) / float(deepOuterSamples) + phi;
      tapRingArea = outerArea;
    }
    ivec2 tap = ivec2(floor(center + h * vec2(cos(theta), sin(theta))));
    if (any(lessThan(tap, ivec2(0))) || any(greaterThanEqual(tap, isize)))
    {
      continue;
    }
    int m = deepTapMipLevel(h, deepMipThreshold, deepMinMip, deepMaxMip);
    // The tap's source texel, through the texel of the minimum level that
    // holds it (where the bounce input B is stored).
    ivec2 sourceTexel = deepRotatedGridDescend(deepCoarseTexel(tap, m, isize), m, deepMinMip, isize);
    ivec2 source = deepRotatedGridSource(sourceTexel, deepMinMip, isize);
    // On a reduced grid the bounce input of a source texel s reads the
    // irradiance of the grid texel s falls into, floor(s / D + 1 / 2)
    // (vtkDeepRadiosityBounceFS, still camera): a receiver gathering from
    // such a texel would light its own source, with a gain of up to 2 per
    // frame at a steep crease (the bound of eq. 4), so it leaves them out,
    // as at full resolution a receiver leaves out its own texel. The test
    // floor((2 s + D) / 2D) == receiver is written without an integer
    // division: a CPU renderer (Mesa llvmpipe) divides lane by lane, and
    // for every tap, whether D > 1 or not (both sides of a branch run).
    ivec2 scaledSource = 2 * source + deepDivisor;
    ivec2 receiverStart = 2 * deepDivisor * receiver;
    if (deepDivisor > 1 && all(greaterThanEqual(scaledSource, receiverStart)) &&
      all(lessThan(scaledSource, receiverStart + 2 * deepDivisor)))
    {
      continue;
    }
    vec2 sourceCenter = vec2(source) + 0.5;
    // Where B is read: the source's texel, or with deepAverageFarTaps the
    // tap's block at its level (vtkDeepRadiosityPass::AverageFarTaps).
    bool averaged = deepAverageFarTaps != 0 && m > deepMinMip;
    ivec2 bounceTexel = averaged ? deepCoarseTexel(tap, m, isize) : sourceTexel;
    int bounceLevel = averaged ? m - deepMinMip : 0;

    // The candidates of this tap: the surface of every layer, and, for
    // SOLID_ANGLE, the area of the patch the tap stands for at each (its
    // screen ring 2 pi h r_p / N pixels^2, times the world area of a pixel
    // at Y's distance, over Y's tilt to the view, at least 0.1), which does
    // not depend on the receiver.
    vec3 Y[2];
    vec3 nY[2];
    vec3 B[2];
    float area[2];
    bool present[2];
    vec4 sourceKey = texelFetch(deepKey, source, 0);
    int candidates = sourceKey.z > 0.0 ? 2 : 1;
    for (int k = 0; k < candidates; ++k)
    {
      vec2 geometry = k == 0 ? sourceKey.xy : sourceKey.zw;
      float dy = geometry.x;
      present[k] = dy > 0.0;
      Y[k] = deepPositionFromDistance(sourceCenter, size, max(dy, 0.0));
      nY[k] = useNormals ? deepUnpackOct16(geometry.y) : vec3(0.0);
      vec4 b = k == 0 ? texelFetch(deepBounce0, bounceTexel, bounceLevel)
                      : texelFetch(deepBounce1, bounceTexel, bounceLevel);
      B[k] = b.a > 0.0 ? b.rgb / b.a : vec3(0.0);
      area[k] = 0.0;
      if (solidAngle && present[k])
      {
        float pixelSize = 1.0 / deepScreenRadius(1.0, dy, size);
        float tilt = max(abs(dot(nY[k], normalize(Y[k]))), 0.1);
        area[k] = tapRingArea * h * pixelSize * pixelSize / tilt;
      }
    }

    for (int j = 0; j < receivers; ++j)
    {
      // The passing candidate with the larger contribution |B (w.n_X)|.
      float bestScore = 0.0;
      vec3 best = vec3(0.0);
      vec3 bestB = vec3(0.0);
      float bestOmega = 0.0; // SOLID_ANGLE: dOmega_i of the best candidate
      for (int k = 0; k < candidates; ++k)
      {
        // Every candidate's terms are computed and its tests folded into
        // one condition, without a `continue`: with one in this loop the
        // gather counted 2.4 times the instructions on a CPU renderer
        // (Mesa llvmpipe, BALANCED, a bunny on a floor, 320 x 240: 481
        // against 203 million, the same pixels).
        vec3 v = Y[k] - X[j];
        float vv = dot(v, v);
        vec3 w = v * inversesqrt(vv);
        float cosX = dot(w, nX[j]);
        float cosY = dot(w, nY[k]);
        vec3 c = B[k] * cosX;
        float score = dot(c, c) + 1.0;
        // Equation 5.
        bool passes = present[k] && vv < r2 && vv > 0.0 && cosX > deepCosineEpsilon &&
          (deepNormalTest == 0 || cosY < -deepCosineEpsilon);
        if (passes && score > bestScore)
        {
          bestScore = score;
          best = c;
          bestB = B[k];
          bestOmega = area[k] * max(-cosY, 0.0) / vv;
        }
      }
      if (bestScore > 0.0)
      {
        sum[j] += solidAngle ? best * bestOmega : best;
        used[j] += 1.0;
        maxB[j] = max(maxB[j], bestB);
      }
    }
  }
  for (int j = 0; j < 2; ++j)
  {
    // Equation 4 (or the chosen estimator) and the confidence M / N, each
    // of this frame's taps standing for tapShare taps.
    float accepted = used[j] * tapShare;
    float norm = deepEstimator == DEEP_ESTIMATOR_ACCEPTED_TAPS ? accepted : float(taps);
    vec3 E = used[j] > 0.0
      ? (solidAngle ? min(sum[j], 2.0 * deepPi * tapShare * maxB[j])
                    : (2.0 * deepPi * tapShare / norm) * sum[j])
      : vec3(0.0);
    E = min(E, vec3(deepIrradianceLimit));
    vec4 result = valid[j] ? vec4(E, min(accepted / float(taps), 1.0)) : vec4(0.0);
    if (j == 0)
    {
      gl_FragData[0] = result;
    }
    else
    {
      gl_FragData[1] = result;
    }
  }
}
