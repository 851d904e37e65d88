using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>The two lens models nerfstudio, instant-ngp, COLMAP and gsplat all read.</summary>
    public enum LensModel
    {
        /// <summary>OpenCV radial-tangential: k1, k2, p1, p2 and optionally k3 (COLMAP OPENCV, or FULL_OPENCV with k3).</summary>
        OpenCv,

        /// <summary>OpenCV fisheye (Kannala–Brandt, equidistant): k1…k4 on the angle θ (COLMAP OPENCV_FISHEYE).</summary>
        OpenCvFisheye,
    }

    /// <summary>
    /// A lens distortion on NORMALISED image coordinates in OpenCV's camera axes: x = X/Z right, y = Y/Z DOWN, Z
    /// forward (pixel = (fx·x_d + cx, fy·y_d + cy), top-left image corner at 0). The sign of p1/p2 depends on y
    /// pointing down; every loader below uses that convention (nerfstudio builds (y − cy)/fy before it undistorts and
    /// flips to OpenGL only afterwards). The formulas, which <see cref="Distort"/> reproduces term for term
    /// (Documentation~/maintainers/lens-distortion.md cites the lines):
    /// <list type="bullet">
    /// <item>OpenCV: r² = x² + y², x_d = x(1 + k1 r² + k2 r⁴ + k3 r⁶) + 2 p1 x y + p2 (r² + 2x²),
    /// y_d = y(1 + k1 r² + k2 r⁴ + k3 r⁶) + 2 p2 x y + p1 (r² + 2y²).</item>
    /// <item>Fisheye: r = √(x² + y²), θ = atan r, θ_d = θ(1 + k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸), (x_d, y_d) = (x, y)·θ_d / r.</item>
    /// </list>
    /// <see cref="Undistort"/> inverts them by Newton's method to a residual of 1e-12 in normalised units.
    /// </summary>
    public sealed class LensDistortion
    {
        /// <summary>Newton stops when the residual is this small (normalised image units; 1e-12 is ~1e-9 pixel at f = 1000).</summary>
        public const double Tolerance = 1e-12;

        const int MaxIterations = 100;

        /// <summary>std::numeric_limits&lt;double&gt;::epsilon(), COLMAP's and instant-ngp's threshold.</summary>
        const double MachineEpsilon = 2.220446049250313e-16;

        public LensDistortion(LensModel model, double k1, double k2, double k3, double k4, double p1, double p2)
        {
            var problems = new List<ValidationProblem>();
            void Finite(string key, double value)
            {
                if (double.IsNaN(value) || double.IsInfinity(value))
                    problems.Add(new ValidationProblem(key, ValidationProblem.Format(value), "must be a finite number.", "Write the lens coefficient as a number."));
            }
            Finite("k1", k1); Finite("k2", k2); Finite("k3", k3); Finite("k4", k4); Finite("p1", p1); Finite("p2", p2);
            // The keys one model does not have are refused rather than dropped: a dropped coefficient is a silently wrong lens.
            if (model == LensModel.OpenCv && k4 != 0)
                problems.Add(new ValidationProblem("k4", ValidationProblem.Format(k4), "is not a coefficient of the OpenCV radial-tangential model (k1, k2, p1, p2, k3).",
                    "Set camera_model to OPENCV_FISHEYE if the lens is a fisheye, or remove k4."));
            if (model == LensModel.OpenCvFisheye && (p1 != 0 || p2 != 0))
                problems.Add(new ValidationProblem("p1, p2", ValidationProblem.Format(p1) + ", " + ValidationProblem.Format(p2),
                    "are not coefficients of the OpenCV fisheye model (k1…k4).", "Set camera_model to OPENCV for a radial-tangential lens, or remove p1 and p2."));
            InvalidParameterException.ThrowIfAny(problems.ToArray());
            Model = model;
            K1 = k1; K2 = k2; K3 = k3; K4 = k4; P1 = p1; P2 = p2;
        }

        public static LensDistortion OpenCv(double k1, double k2, double p1, double p2, double k3 = 0) =>
            new LensDistortion(LensModel.OpenCv, k1, k2, k3, 0, p1, p2);

        public static LensDistortion Fisheye(double k1, double k2, double k3, double k4) =>
            new LensDistortion(LensModel.OpenCvFisheye, k1, k2, k3, k4, 0, 0);

        public LensModel Model { get; }
        public double K1 { get; }
        public double K2 { get; }
        public double K3 { get; }
        public double K4 { get; }
        public double P1 { get; }
        public double P2 { get; }

        /// <summary>
        /// Whether every coefficient is 0. An OpenCV lens with no coefficients is a pinhole; a fisheye with none is
        /// still the equidistant projection (r_d = atan r), which is NOT a pinhole.
        /// </summary>
        public bool IsPinhole => Model == LensModel.OpenCv && K1 == 0 && K2 == 0 && K3 == 0 && P1 == 0 && P2 == 0;

        /// <summary>nerfstudio's <c>camera_model</c> (cameras.py <c>CAMERA_MODEL_TO_TYPE</c>).</summary>
        public string CameraModelName => Model == LensModel.OpenCv ? "OPENCV" : "OPENCV_FISHEYE";

        /// <summary>COLMAP's model: OPENCV, FULL_OPENCV when k3 ≠ 0 (OPENCV has no k3), or OPENCV_FISHEYE.</summary>
        public string ColmapModelName => Model == LensModel.OpenCvFisheye ? "OPENCV_FISHEYE" : K3 != 0 ? "FULL_OPENCV" : "OPENCV";

        /// <summary>COLMAP's model id (models.h <c>CameraModelId</c>: OPENCV 4, OPENCV_FISHEYE 5, FULL_OPENCV 6).</summary>
        public int ColmapModelId => Model == LensModel.OpenCvFisheye ? 5 : K3 != 0 ? 6 : 4;

        /// <summary>
        /// COLMAP's parameter list for this lens on <paramref name="k"/>, in models.h's order: OPENCV fx fy cx cy k1 k2 p1 p2;
        /// FULL_OPENCV fx fy cx cy k1 k2 p1 p2 k3 k4 k5 k6 (k4…k6, the rational denominator, are 0); OPENCV_FISHEYE fx fy cx cy k1 k2 k3 k4.
        /// </summary>
        public double[] ColmapParams(CameraIntrinsics k)
        {
            if (Model == LensModel.OpenCvFisheye) return new[] { k.FlX, k.FlY, k.Cx, k.Cy, K1, K2, K3, K4 };
            if (K3 != 0) return new[] { k.FlX, k.FlY, k.Cx, k.Cy, K1, K2, P1, P2, K3, 0, 0, 0 };
            return new[] { k.FlX, k.FlY, k.Cx, k.Cy, K1, K2, P1, P2 };
        }

        /// <summary>The normalised point (x, y) of an ideal pinhole as this lens images it.</summary>
        public void Distort(double x, double y, out double xd, out double yd)
        {
            if (Model == LensModel.OpenCv)
            {
                var r2 = x * x + y * y;
                var radial = 1 + r2 * (K1 + r2 * (K2 + r2 * K3));
                xd = x * radial + 2 * P1 * x * y + P2 * (r2 + 2 * x * x);
                yd = y * radial + 2 * P2 * x * y + P1 * (r2 + 2 * y * y);
                return;
            }
            var r = Math.Sqrt(x * x + y * y);
            // COLMAP and instant-ngp skip the scaling below machine epsilon; the limit of θ_d/r there is 1.
            if (!(r > MachineEpsilon)) { xd = x; yd = y; return; }
            var theta = Math.Atan(r);
            var scale = FisheyeAngle(theta) / r;
            xd = x * scale;
            yd = y * scale;
        }

        /// <summary>
        /// The Jacobian ∂(x_d, y_d)/∂(x, y) at the ideal point (x, y), row-major [[a, b], [c, d]]. OpenCV: the derivatives
        /// nerfstudio's <c>_compute_residual_and_jacobian</c> writes out; fisheye: (x, y)·s(r) with s = θ_d/r has
        /// J = s·I + (s′/r)·(x, y)ᵀ(x, y), s′ = (θ_d′(θ)/(1 + r²) − s)/r.
        /// </summary>
        public void Jacobian(double x, double y, out double a, out double b, out double c, out double d)
        {
            if (Model == LensModel.OpenCv)
            {
                var r2 = x * x + y * y;
                var radial = 1 + r2 * (K1 + r2 * (K2 + r2 * K3));
                var dr = K1 + r2 * (2 * K2 + r2 * 3 * K3);
                a = radial + 2 * x * x * dr + 2 * P1 * y + 6 * P2 * x;
                b = 2 * x * y * dr + 2 * P1 * x + 2 * P2 * y;
                c = 2 * x * y * dr + 2 * P2 * y + 2 * P1 * x;
                d = radial + 2 * y * y * dr + 2 * P2 * x + 6 * P1 * y;
                return;
            }
            var r = Math.Sqrt(x * x + y * y);
            if (!(r > 1e-8))
            {
                // s(r) = 1 − r²/3 + k1 r² + O(r⁴): J = I to within 1e-16 here.
                a = d = 1; b = c = 0;
                return;
            }
            var theta = Math.Atan(r);
            var t2 = theta * theta;
            var s = FisheyeAngle(theta) / r;
            var dThetaD = 1 + t2 * (3 * K1 + t2 * (5 * K2 + t2 * (7 * K3 + t2 * 9 * K4)));
            var sPrimeOverR = (dThetaD / (1 + r * r) - s) / (r * r);
            a = s + sPrimeOverR * x * x;
            b = sPrimeOverR * x * y;
            c = b;
            d = s + sPrimeOverR * y * y;
        }

        /// <summary>θ_d = θ(1 + k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸).</summary>
        public double FisheyeAngle(double theta)
        {
            var t2 = theta * theta;
            return theta * (1 + t2 * (K1 + t2 * (K2 + t2 * (K3 + t2 * K4))));
        }

        /// <summary>
        /// The ideal pinhole point whose image is (xd, yd): Newton's method from (xd, yd) until the residual
        /// |distort(x, y) − (xd, yd)| is at most <see cref="Tolerance"/>. False (and the last iterate) when it does not
        /// converge — a point outside the lens's monotonic range, which no camera ray reaches.
        /// </summary>
        public bool Undistort(double xd, double yd, out double x, out double y)
        {
            return Model == LensModel.OpenCv ? UndistortOpenCv(xd, yd, out x, out y) : UndistortFisheye(xd, yd, out x, out y);
        }

        bool UndistortOpenCv(double xd, double yd, out double x, out double y)
        {
            x = xd; y = yd;
            for (var i = 0; i < MaxIterations; i++)
            {
                var r2 = x * x + y * y;
                var d = 1 + r2 * (K1 + r2 * (K2 + r2 * K3));
                var fx = x * d + 2 * P1 * x * y + P2 * (r2 + 2 * x * x) - xd;
                var fy = y * d + 2 * P2 * x * y + P1 * (r2 + 2 * y * y) - yd;
                Jacobian(x, y, out var fxX, out var fxY, out var fyX, out var fyY);
                var det = fxX * fyY - fxY * fyX;
                // A root where the lens has folded over is not the ray a camera images there: only the unfolded part,
                // where the Jacobian keeps orientation and points outward (det > 0 and trace > 0), counts.
                if (Math.Abs(fx) <= Tolerance && Math.Abs(fy) <= Tolerance) return det > 0 && fxX + fyY > 0;
                if (det == 0 || double.IsNaN(det)) return false;
                x -= (fx * fyY - fy * fxY) / det;
                y -= (fy * fxX - fx * fyX) / det;
                if (double.IsNaN(x) || double.IsNaN(y) || double.IsInfinity(x) || double.IsInfinity(y)) return false;
            }
            return false;
        }

        bool UndistortFisheye(double xd, double yd, out double x, out double y)
        {
            // The fisheye model is radial: solve θ_d(θ) = ρ_d for θ in [0, π/2), then r = tan θ on the same direction.
            var rhoD = Math.Sqrt(xd * xd + yd * yd);
            x = xd; y = yd;
            if (rhoD == 0) return true;
            var theta = Math.Min(rhoD, 1.5);
            for (var i = 0; i < MaxIterations; i++)
            {
                var f = FisheyeAngle(theta) - rhoD;
                var t2 = theta * theta;
                var derivative = 1 + t2 * (3 * K1 + t2 * (5 * K2 + t2 * (7 * K3 + t2 * 9 * K4)));
                if (Math.Abs(f) <= Tolerance)
                {
                    // Only the rising part of θ_d(θ), in front of the camera, is imaged.
                    if (!(theta >= 0 && theta < Math.PI / 2 && derivative > 0)) return false;
                    var scale = Math.Tan(theta) / rhoD;
                    x = xd * scale;
                    y = yd * scale;
                    return true;
                }
                if (!(derivative > 0)) return false;
                theta -= f / derivative;
                if (double.IsNaN(theta)) return false;
            }
            return false;
        }

        /// <summary>The non-zero coefficients as "k1 = …, p1 = …" for messages.</summary>
        public string Describe()
        {
            var parts = new List<string>();
            void Add(string key, double value) { if (value != 0) parts.Add(key + " = " + value.ToString("R", CultureInfo.InvariantCulture)); }
            Add("k1", K1); Add("k2", K2); Add("k3", K3); Add("k4", K4); Add("p1", P1); Add("p2", P2);
            return CameraModelName + (parts.Count > 0 ? " (" + string.Join(", ", parts) + ")" : "");
        }
    }
}
