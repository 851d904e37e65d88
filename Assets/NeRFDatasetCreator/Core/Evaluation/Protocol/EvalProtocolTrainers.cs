using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The fixed parts of the protocol — compositing rule, SSIM variant, LPIPS network and range — and, per background,
    /// the trainer flags that realise it. Every flag is read from the trainer's own code; the file and line are in
    /// Documentation~/maintainers/eval-protocol.md (graphdeco-inria/gaussian-splatting 82bc469 arguments/__init__.py
    /// <c>_white_background</c> → <c>-w</c>, <c>random_background</c>; train.py <c>bg_color</c>; nerfstudio 50e0e3c
    /// splatfacto/nerfacto <c>background_color</c>, blender_dataparser <c>alpha_color</c>; nerf-pytorch 63a5a63
    /// <c>--white_bkgd</c>; instant-ngp abe236e <c>random_bg_color</c>, run.py's black evaluation background).
    /// </summary>
    public static class EvalProtocolTrainers
    {
        public const string Compositing =
            "straight alpha over the background on the stored sRGB values: c = rgb/255 · a + bg · (1 − a), a = alpha/255 (no linearisation), " +
            "as 3DGS scene/dataset_readers.py readCamerasFromTransforms, nerf-pytorch run_nerf.py --white_bkgd and nerfstudio InputDataset (alpha_color) do";

        public const string Ssim =
            "3dgs: utils/loss_utils.py ssim — 11×11 Gaussian window σ 1.5, zero padding 5, C1 = 0.01², C2 = 0.03², mean over pixels and channels (evaluate computes it in double precision; " +
            "3DGS metrics.py runs it in float32 and prints values up to ~2e-4 different)";

        public const string LpipsNetwork = "vgg";

        public const string LpipsRange =
            "[-1, 1] (images in [0, 1] mapped by 2x − 1, LPIPS's normalize=True). 3DGS metrics.py feeds its lpipsPyTorch VGG images in [0, 1] unscaled (graphdeco-inria/gaussian-splatting #1239); " +
            "nerfstudio ns-eval uses AlexNet with normalize=True: neither figure is this protocol's LPIPS, so evaluate shows them labelled and compares only PSNR (and 3DGS's SSIM)";

        /// <summary>Trainer → the flags that train and render on <paramref name="protocol"/>'s background.</summary>
        public static IReadOnlyList<KeyValuePair<string, string>> Flags(EvalProtocol protocol)
        {
            var opaque = protocol.Background == EvalProtocol.Dataset;
            string gs, ns, nerf, ngp;
            switch (protocol.Background)
            {
                case EvalProtocol.Black:
                    gs = "no -w (train.py bg_color [0, 0, 0] unless --white_background)";
                    ns = "--pipeline.model.background-color black; with the blender-data dataparser also --alpha-color black (its default is white)";
                    nerf = "no --white_bkgd (run_nerf.py then drops alpha and keeps the stored RGB)";
                    ngp = "training uses random background colours by default; --screenshot_transforms renders RGBA, which evaluate composites over black; scripts/run.py --test_transforms also scores on black";
                    break;
                case EvalProtocol.Random:
                    gs = "--random_background -w (a random colour per training step; render.py and metrics.py then use white)";
                    ns = "--pipeline.model.background-color random (ns-eval then scores splatfacto over (0.149, 0.165, 0.216) and nerfacto over black, not white)";
                    nerf = "no equivalent (only --white_bkgd): use --white_bkgd";
                    ngp = "the default (random_bg_color = true); screenshots are RGBA, composited over white by evaluate";
                    break;
                default:
                    if (opaque)
                    {
                        gs = ns = nerf = ngp = "none needed: the images are opaque (" + (protocol.DatasetBackground ?? protocol.ColourText) + "), so every trainer sees the dataset's own background";
                        break;
                    }
                    gs = "-w (--white_background: train.py bg_color [1, 1, 1], readCamerasFromTransforms composites the images over white)";
                    ns = "--pipeline.model.background-color white (splatfacto's default is random, nerfacto's last_sample); the blender-data dataparser's --alpha-color is white by default";
                    nerf = "--white_bkgd";
                    ngp = "training uses random background colours by default; --screenshot_transforms renders RGBA, which evaluate composites over white (scripts/run.py --test_transforms scores on black)";
                    break;
            }
            return new[]
            {
                new KeyValuePair<string, string>("3dgs", gs),
                new KeyValuePair<string, string>("nerfstudio", ns),
                new KeyValuePair<string, string>("nerf-pytorch", nerf),
                new KeyValuePair<string, string>("instant-ngp", ngp),
            };
        }
    }
}
