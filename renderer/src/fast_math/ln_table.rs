//! The natural logarithm of floats of at least 1 by a table of 128 logarithms: in
//! WebAssembly a few table loads and a short polynomial cost less than the division and
//! the long series of [`super::series_ln`].

use super::{LN_2_HI, LN_2_LO};

/// ln x for an `x` from 1 up to 2^1022, within an ulp or two. x is rounded to c, a float
/// with seven bits after its leading one (so c = 2^e (1 + i/128)), and
/// ln x = e ln 2 + ln(1 + i/128) + ln(1 + r) with r = (x - c)/c, where x - c is exact and
/// |r| ≤ 2^-8, so that ln(1 + r) = r - r²/2 + … + r⁷/7 reaches the last bit. Rounding
/// x to the nearest such c rather than down makes c = x exactly for x just above 1, where
/// the logarithm is small: its table entry is then 0, and nothing cancels.
#[inline(always)]
pub fn ln_at_least_one(x: f64) -> f64 {
    const LOW_BITS: u64 = (1 << 45) - 1;
    let c_bits = (x.to_bits() + (1 << 44)) & !LOW_BITS;
    let [inverse, ln_bucket] = BUCKETS[(c_bits >> 45) as usize & 127];
    // 2^-e, from the exponent field E = e + 1023 of c: the float whose field is 2046 - E.
    let exponent_bits = c_bits & (0x7ff << 52);
    let down = f64::from_bits((2046 << 52) - exponent_bits);
    let r = (x - f64::from_bits(c_bits)) * down * inverse;
    let e = ((exponent_bits >> 52) as i64 - 1023) as f64;
    // Estrin's scheme: short independent chains, which an interpreter runs faster.
    let (r2, third) = (r * r, |a: f64, b: f64| a + r * b);
    let r4 = r2 * r2;
    let tail = third(-0.5, 1.0 / 3.0) + r2 * third(-0.25, 0.2) + r4 * third(-1.0 / 6.0, 1.0 / 7.0);
    e * LN_2_HI + (ln_bucket + (e * LN_2_LO + (r + r2 * tail)))
}

/// For each i below 128, 1/(1 + i/128) and ln(1 + i/128), each rounded to the nearest
/// float.
static BUCKETS: [[f64; 2]; 128] = {
    let mut buckets = [[0.0; 2]; 128];
    let mut i = 0;
    while i < 128 {
        buckets[i] = [128.0 / (128 + i) as f64, LN_BUCKETS[i]];
        i += 1;
    }
    buckets
};

/// ln(1 + i/128), rounded to the nearest float (from a 200-bit evaluation).
const LN_BUCKETS: [f64; 128] = [
    0.0,
    0.007782140442054949,
    0.015504186535965254,
    0.02316705928153438,
    0.030771658666753687,
    0.0383188643021366,
    0.0458095360312942,
    0.053244514518812285,
    0.06062462181643484,
    0.06795066190850775,
    0.07522342123758753,
    0.08244366921107459,
    0.08961215868968714,
    0.09672962645855111,
    0.10379679368164356,
    0.11081436634029011,
    0.11778303565638346,
    0.12470347850095724,
    0.13157635778871926,
    0.13840232285911913,
    0.1451820098444979,
    0.15191604202584197,
    0.15860503017663857,
    0.16524957289530717,
    0.17185025692665923,
    0.1784076574728183,
    0.184922338494012,
    0.19139485299962947,
    0.19782574332991987,
    0.2042155414286909,
    0.21056476910734964,
    0.21687393830061436,
    0.22314355131420976,
    0.22937410106484582,
    0.2355660713127669,
    0.24171993688714516,
    0.24783616390458127,
    0.25391520998096345,
    0.25995752443692605,
    0.26596354849713794,
    0.27193371548364176,
    0.2778684510034563,
    0.2837681731306446,
    0.28963329258304266,
    0.2954642128938359,
    0.3012613305781618,
    0.3070250352949119,
    0.3127557100038969,
    0.3184537311185346,
    0.324119468654212,
    0.329753286372468,
    0.3353555419211378,
    0.3409265869705932,
    0.34646676734620857,
    0.3519764231571782,
    0.3574558889218038,
    0.3629054936893685,
    0.3683255611587076,
    0.37371640979358406,
    0.37907835293496944,
    0.38441169891033206,
    0.3897167511400252,
    0.394993808240869,
    0.4002431641270127,
    0.4054651081081644,
    0.4106599249852684,
    0.415827895143711,
    0.42096929464412963,
    0.4260843953109001,
    0.4311734648183713,
    0.43623676677491807,
    0.4412745608048752,
    0.44628710262841953,
    0.45127464413945856,
    0.4562374334815876,
    0.46117571512217015,
    0.46608972992459924,
    0.470979715218791,
    0.4758459048699639,
    0.4806885293457519,
    0.4855078157817008,
    0.4903039880451938,
    0.4950772667978515,
    0.4998278695564493,
    0.5045560107523953,
    0.5092619017898079,
    0.5139457511022343,
    0.5186077642080457,
    0.5232481437645479,
    0.5278670896208424,
    0.5324647988694718,
    0.5370414658968836,
    0.5415972824327444,
    0.5461324375981357,
    0.5506471179526623,
    0.5551415075405016,
    0.5596157879354227,
    0.564070138284803,
    0.5685047353526688,
    0.5729197535617855,
    0.5773153650348236,
    0.5816917396346225,
    0.5860490450035782,
    0.5903874466021763,
    0.5947071077466928,
    0.5990081896460834,
    0.6032908514380843,
    0.6075552502245418,
    0.6118015411059929,
    0.616029877215514,
    0.6202404097518576,
    0.6244332880118935,
    0.6286086594223741,
    0.6327666695710378,
    0.6369074622370692,
    0.6410311794209312,
    0.6451379613735847,
    0.6492279466251099,
    0.6533012720127457,
    0.65735807270836,
    0.661398482245365,
    0.6654226325450905,
    0.6694306539426292,
    0.6734226752121667,
    0.6773988235918061,
    0.6813592248079031,
    0.6853040030989194,
    0.689233281238809,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_logarithm_of_floats_of_at_least_one_is_within_an_ulp() {
        // Each side of every boundary between buckets, where x rounds to the next c, and
        // within each bucket, from 1 up to 2^600.
        let mut worst: f64 = 0.0;
        for e in (0..600).step_by(7) {
            let scale = f64::powi(2.0, e);
            for i in 0..128 {
                let edge = scale * (1.0 + (f64::from(i) + 0.5) / 128.0);
                let inside = scale * (1.0 + (f64::from(i) + 0.3) / 128.0);
                for v in [edge.next_down(), edge, edge.next_up(), inside] {
                    let want = v.ln();
                    let ulp = f64::EPSILON * want.max(f64::MIN_POSITIVE);
                    worst = worst.max((ln_at_least_one(v) - want).abs() / ulp);
                }
            }
        }
        assert!(worst <= 1.0, "{worst} ulps");
        assert_eq!(ln_at_least_one(1.0), 0.0);
        assert_eq!(ln_at_least_one(1.0f64.next_up()), 1.0f64.next_up().ln());
    }
}
