//! Antialiasing: how many camera rays each pixel gets and where. Method 3 samples each
//! pixel at random until its mean is known to the threshold with `Antialias_Confidence`.
//! Method 2 is POV-Ray's
//! adaptive recursive supersampling: every pixel starts from the samples at its four
//! corners (shared with its neighbours), and a square whose corners differ by the threshold
//! or more is split into four, up to `depth - 1` times, jittered. Method 1 traces pixel
//! centres and supersamples a `depth` × `depth` grid wherever a pixel differs from a
//! neighbour. Colours are compared after the antialiasing gamma curve, as POV-Ray does.

use crate::camera::Camera;
use crate::colour::{Curve, EncodeTable, Sample};
use crate::fast_math;
use crate::focal_blur::FocalBlur;
use crate::mesh_camera::MeshRays;
use crate::ray::Ray;
use crate::tracer::{Tracer, World};

mod subdivider;

pub use subdivider::Subdivider;

/// Everything needed to turn image positions into samples.
pub struct Sampler<'a> {
    pub world: &'a World,
    pub camera: &'a Camera,
    pub width: f64,
    pub height: f64,
    pub threshold: f64,
    pub depth: u32,
    pub jitter: f64,
    /// Working colour to the values compared against the threshold.
    pub compare: CompareCurve,
}

/// How sample colours are prepared for the threshold test: from working space to linear
/// light (`assumed_gamma`), then through the antialiasing gamma (tabulated: the test needs
/// no more than three decimals).
#[derive(Debug, Clone)]
pub struct CompareCurve {
    pub working: Curve,
    pub aa: EncodeTable,
}

impl CompareCurve {
    pub fn apply(&self, s: Sample) -> Sample {
        let linear = self.working.decode_vec(s.colour);
        Sample::new(self.aa.encode_vec(linear), s.transmit)
    }
}

impl Sampler<'_> {
    /// The sample at image position `(x, y)` (pixel units from the top-left): one camera
    /// ray, or with focal blur the mean of rays through the lens from around it. Out of
    /// line: inlined into its callers, it made the plugin dearer to interpret (3.6% more
    /// instructions for basic.pov in wasmi, when measured).
    #[inline(never)]
    pub fn trace(&self, tracer: &mut Tracer<'_>, x: f64, y: f64) -> Sample {
        if let Some(blur) = &self.camera.focal_blur {
            return self.blurred(tracer, blur, x, y);
        }
        let ray = self.camera.ray(x, y, self.width, self.height);
        trace_camera_ray(tracer, ray.as_ref())
    }

    /// The samples at the image positions `points`, in order, appended to `out`: each as
    /// [`Sampler::trace`] gives it, but through a camera without focal blur all the rays'
    /// nearest hits are found before any is shaded (see [`Tracer::trace_primaries`]).
    pub fn trace_all(&self, tracer: &mut Tracer<'_>, points: &[(f64, f64)], out: &mut Vec<Sample>) {
        if self.camera.focal_blur.is_some() {
            out.extend(points.iter().map(|&(x, y)| self.trace(tracer, x, y)));
            return;
        }
        let rays: Vec<Option<Ray>> = points
            .iter()
            .map(|&(x, y)| self.camera.ray(x, y, self.width, self.height))
            .collect();
        tracer.trace_primaries(&rays, out);
    }

    /// [`Sampler::trace`] through a camera with focal blur: kept out of line, so that the
    /// interpreted plugin's calls of the common case set up no room for it.
    #[inline(never)]
    fn blurred(&self, tracer: &mut Tracer<'_>, blur: &FocalBlur, x: f64, y: f64) -> Sample {
        blur.pixel(position_seed(x, y), |s| {
            let (dx, dy) = s.pixel_offset;
            let pinhole = self.camera.ray(x + dx, y + dy, self.width, self.height);
            let ray = pinhole.and_then(|r| blur.through_lens(&r, s.lens));
            trace_camera_ray(tracer, ray.as_ref())
        })
    }

    /// The pixel holding image position `(x, y)` through a mesh camera: the mean of its
    /// rays that have a face. A pixel without any is left as POV-Ray
    /// leaves it, transparent black.
    pub fn mesh_pixel(&self, tracer: &mut Tracer<'_>, mesh: &MeshRays, x: f64, y: f64) -> Sample {
        let size = (self.width as u32, self.height as u32);
        let at = MeshRays::pixel_at(x, y, size);
        let mut sum = Sample::default();
        let mut rays = 0;
        for r in 0..mesh.rays_per_pixel {
            if let Some(ray) = mesh.pixel_ray(r, at, size) {
                sum = sum + tracer.trace_primary(&ray);
                rays += 1;
            }
        }
        if rays == 0 {
            return Sample::new(glam::DVec3::ZERO, 1.0);
        }
        sum * (1.0 / f64::from(rays))
    }

    fn differ(&self, a: Sample, b: Sample) -> bool {
        self.compare.apply(a).distance(self.compare.apply(b)) >= self.threshold
    }

    /// A sample with its colour as the threshold test compares it.
    pub fn compared(&self, s: Sample) -> Compared {
        Compared {
            sample: s,
            encoded: self.compare.apply(s),
        }
    }

    /// A pseudo-random offset in [-0.5, 0.5)² for a sample position, the same whatever
    /// thread or order traces it.
    fn jitter_at(&self, x: f64, y: f64) -> (f64, f64) {
        let h = position_seed(x, y);
        let a = (h >> 11) as f64 / (1u64 << 53) as f64;
        let b = (mix(h) >> 11) as f64 / (1u64 << 53) as f64;
        (a - 0.5, b - 0.5)
    }

    /// Where the sample meant for image position `(x, y)` is taken: moved by up to half
    /// of `scale` each way, by [`Sampler::jitter_at`].
    pub(crate) fn jittered(&self, x: f64, y: f64, scale: f64) -> (f64, f64) {
        if scale > 0.0 {
            let (jx, jy) = self.jitter_at(x, y);
            (x + jx * scale, y + jy * scale)
        } else {
            (x, y)
        }
    }
}

/// A sample and its colour prepared for the threshold test, computed once per sample.
#[derive(Debug, Clone, Copy, Default)]
pub struct Compared {
    pub sample: Sample,
    encoded: Sample,
}

/// Takes the ray where it lies, in the camera's answer: a ray moved out of it was copied
/// for every sample in WebAssembly.
fn trace_camera_ray(tracer: &mut Tracer<'_>, ray: Option<&Ray>) -> Sample {
    match ray {
        Some(ray) => tracer.trace_primary(ray),
        None => Sample::NO_RAY,
    }
}

/// A hash of an image position, the same whatever thread or order traces it.
fn position_seed(x: f64, y: f64) -> u64 {
    let qx = fast_math::round(x * 65536.0) as i64 as u64;
    let qy = fast_math::round(y * 65536.0) as i64 as u64;
    mix(qx.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ qy)
}

fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// How many supersamples method 1 takes in a pixel: a `depth` × `depth` grid.
pub fn grid_points(sampler: &Sampler<'_>) -> usize {
    let n = sampler.depth.max(1) as usize;
    n * n
}

/// Method 1's supersamples of the pixel at `(x, y)`: the jittered positions of its grid
/// (see [`grid_points`]), row by row.
pub fn grid_positions(sampler: &Sampler<'_>, x: u32, y: u32) -> impl Iterator<Item = (f64, f64)> {
    let n = sampler.depth.max(1);
    let step = 1.0 / f64::from(n);
    let scale = sampler.jitter / f64::from(n);
    (0..n).flat_map(move |j| {
        (0..n).map(move |i| {
            let px = f64::from(x) + (f64::from(i) + 0.5) * step;
            let py = f64::from(y) + (f64::from(j) + 0.5) * step;
            sampler.jittered(px, py, scale)
        })
    })
}

/// Method 1's pixel: the samples of its grid (see [`grid_positions`]) averaged with the
/// centre sample.
pub fn grid_mean(centre: Sample, grid: &[Sample]) -> Sample {
    let mut sum = centre;
    for &s in grid {
        sum = sum + s;
    }
    sum * (1.0 / (grid.len() + 1) as f64)
}

/// Method 1's test: whether a pixel differs from any of its four neighbours.
pub fn needs_supersampling(sampler: &Sampler<'_>, centre: Sample, neighbours: &[Sample]) -> bool {
    neighbours.iter().any(|n| sampler.differ(centre, *n))
}

/// Method 3, stochastic supersampling: every pixel takes random samples until the
/// confidence interval of its mean, estimated from its own samples and its neighbours'
/// first ones, is within the threshold (summed over red, green, blue and transmittance),
/// or it has `4^depth` samples. `first` holds each pixel's first sample; `neighbours`
/// the first samples of the pixels around it.
pub fn stochastic_pixel(
    sampler: &Sampler<'_>,
    tracer: &mut Tracer<'_>,
    x: u32,
    y: u32,
    first: Sample,
    neighbours: &[Sample],
    confidence: f64,
) -> Sample {
    let max_samples = 1u32 << (2 * sampler.depth.min(9));
    let z = inverse_normal_cdf((1.0 + confidence.clamp(0.0, 0.999_999)) / 2.0);
    let mut rng = mix((u64::from(x) << 32) ^ u64::from(y) ^ 0x5bd1_e995);
    let mut stats = Moments::default();
    for n in neighbours {
        stats.add(sampler.compare.apply(*n));
    }
    stats.add(sampler.compare.apply(first));
    let mut sum = first;
    let mut count = 1u32;
    while count < max_samples {
        let n = f64::from(stats.count);
        if stats.count > 1 {
            let delta = stats.spread() * (z / n.sqrt());
            if delta <= sampler.threshold {
                break;
            }
        }
        rng = mix(rng);
        let jx = (rng >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
        rng = mix(rng);
        let jy = (rng >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
        let s = sampler.trace(tracer, f64::from(x) + 0.5 + jx, f64::from(y) + 0.5 + jy);
        stats.add(sampler.compare.apply(s));
        sum = sum + s;
        count += 1;
    }
    sum * (1.0 / f64::from(count))
}

/// Running sums for a sample variance per channel.
#[derive(Debug, Default)]
pub struct Moments {
    pub count: u32,
    sum: [f64; 4],
    squares: [f64; 4],
}

impl Moments {
    pub fn add(&mut self, s: Sample) {
        let v = [s.colour.x, s.colour.y, s.colour.z, s.transmit];
        self.count += 1;
        for ((sum, square), value) in self.sum.iter_mut().zip(&mut self.squares).zip(v) {
            *sum += value;
            *square += value * value;
        }
    }

    /// The sample variance of channel `i`.
    pub fn variance(&self, i: usize) -> f64 {
        let n = f64::from(self.count);
        ((self.squares[i] - self.sum[i] * self.sum[i] / n) / (n - 1.0)).max(0.0)
    }

    /// The summed standard deviations of the four channels.
    fn spread(&self) -> f64 {
        (0..4).map(|i| self.variance(i).sqrt()).sum()
    }
}

/// The standard normal quantile (Acklam's rational approximation, relative error below
/// 1.2e-9), for the confidence factors of method 3 and focal blur.
pub fn inverse_normal_cdf(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969_683_028_665_376e1,
        2.209_460_984_245_205e2,
        -2.759_285_104_469_687e2,
        1.383_577_518_672_69e2,
        -3.066_479_806_614_716e1,
        2.506_628_277_459_239,
    ];
    const B: [f64; 5] = [
        -5.447_609_879_822_406e1,
        1.615_858_368_580_409e2,
        -1.556_989_798_598_866e2,
        6.680_131_188_771_972e1,
        -1.328_068_155_288_572e1,
    ];
    const C: [f64; 6] = [
        -7.784_894_002_430_293e-3,
        -3.223_964_580_411_365e-1,
        -2.400_758_277_161_838,
        -2.549_732_539_343_734,
        4.374_664_141_464_968,
        2.938_163_982_698_783,
    ];
    const D: [f64; 4] = [
        7.784_695_709_041_462e-3,
        3.224_671_290_700_398e-1,
        2.445_134_137_142_996,
        3.754_408_661_907_416,
    ];
    let p = p.clamp(1e-12, 1.0 - 1e-12);
    let tail = |q: f64| {
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    };
    if p < 0.02425 {
        tail((-2.0 * p.ln()).sqrt())
    } else if p > 1.0 - 0.02425 {
        -tail((-2.0 * (1.0 - p).ln()).sqrt())
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_quantiles() {
        assert!((inverse_normal_cdf(0.95) - 1.644_853_6).abs() < 1e-6);
        assert!((inverse_normal_cdf(0.5)).abs() < 1e-12);
        assert!((inverse_normal_cdf(0.001) + 3.090_232_3).abs() < 1e-6);
    }
}
