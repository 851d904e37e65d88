using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The per-view stages composed — lens resampling, motion blur's blurred and sharp images, exposure (the clean image,
    /// the gains, the EXIF), label ids, encoding — write byte for byte what they wrote before the stage order moved out of
    /// the Editor into Core (issue 31). The expected SHA-256 sums of every file the analytic dataset writes were taken
    /// from the code before the move (commit 261f467, where the test support ordered the stages itself) running this very
    /// test; a sum that changes means an output changed. Re-pinned since: the four depth PNGs of "lens-blur-shared" (data
    /// passes at the supersampled size), when a pixel's depth became the harmonic mean of its block's central samples
    /// (issue 32 item 19) — those very files are shown to hold the analytic depth at each pixel centre by
    /// <see cref="DepthAtPixelCentreTests"/>, which checks their sums against these.
    /// </summary>
    [TestFixture]
    public class ViewPipelineBytesTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        internal static AnalyticDataset.Options Options(bool lens, bool dataAtOutputSize, bool blur)
        {
            var options = new AnalyticDataset.Options
            {
                Width = 48, Height = 36, Supersampling = 2, Train = 2, Val = 1, Test = 1, PointCloud = 0,
                DataAtOutputSize = dataAtOutputSize,
                Labels = true,
                Configure = s => s.Exposure.Mode = ExposureMode.Random,
            };
            if (lens)
            {
                options.Lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 };
                options.ThroughWideRender = true;
                options.VerticalFovDegrees = 70;
                options.Distance = 1.8;
            }
            // A global shutter: a lens refuses a rolling one.
            if (blur) options.MotionBlur = new MotionBlurSettings { Enabled = true, Camera = ShutterCameraMotion.Shake, ShakeDistance = 0.1, ShakeDegrees = 1, SubFrames = 4 };
            return options;
        }

        static IEnumerable<TestCaseData> Cases()
        {
            // Lens + labels + exposure + blur, depth and normals in the colour frame (one frame resampled for both).
            yield return new TestCaseData("lens-blur-shared", true, false, true).SetName("ViewPipelineBytes_LensBlurLabelsExposure_SharedDataFrame");
            // The same with depth and normals rendered at the output size (a data frame of its own, resampled apart).
            yield return new TestCaseData("lens-blur-apart", true, true, true).SetName("ViewPipelineBytes_LensBlurLabelsExposure_DataFrameApart");
            // Lens + labels + exposure without blur (the sharp image is the colour image).
            yield return new TestCaseData("lens-sharp", true, true, false).SetName("ViewPipelineBytes_LensLabelsExposure");
            // Blur + labels + exposure without a lens.
            yield return new TestCaseData("blur", false, true, true).SetName("ViewPipelineBytes_BlurLabelsExposure");
        }

        [TestCaseSource(nameof(Cases))]
        public void EveryWrittenFileKeepsItsBytes(string name, bool lens, bool dataAtOutputSize, bool blur)
        {
            var folder = AnalyticDataset.Write(_temp.Path, name, Options(lens, dataAtOutputSize, blur));
            var sums = Sums(folder);
            TestContext.WriteLine(string.Join("\n", sums.Select(p => "[\"" + name + "/" + p.Key + "\"] = \"" + p.Value + "\",")));
            var expected = Expected.Where(p => p.Key.StartsWith(name + "/", StringComparison.Ordinal))
                .ToDictionary(p => p.Key.Substring(name.Length + 1), p => p.Value);
            Assert.That(sums.Keys, Is.EquivalentTo(expected.Keys), "the files written");
            foreach (var file in sums) Assert.That(file.Value, Is.EqualTo(expected[file.Key]), file.Key);
        }

        /// <summary>The SHA-256 of every file under <paramref name="folder"/>, by its path relative to it ('/' separated).</summary>
        internal static SortedDictionary<string, string> Sums(string folder)
        {
            var sums = new SortedDictionary<string, string>(StringComparer.Ordinal);
            using (var sha = SHA256.Create())
                foreach (var path in Directory.GetFiles(folder, "*", SearchOption.AllDirectories))
                {
                    var relative = path.Substring(folder.Length + 1).Replace('\\', '/');
                    sums[relative] = string.Concat(sha.ComputeHash(AtTheSumsVersion(File.ReadAllBytes(path), relative)).Select(b => b.ToString("x2")));
                }
            return sums;
        }

        /// <summary>
        /// dataset_config.json records the plugin's version, which changes with every release: the sums were taken at
        /// 0.1.0, so the version is written back as 0.1.0 before hashing; and its <c>unity_frame</c> block (added by
        /// issue 34 after the sums, checked by UnityFrameRecordTests) is left out. Every other byte counts.
        /// </summary>
        static byte[] AtTheSumsVersion(byte[] bytes, string relative)
        {
            if (!relative.EndsWith(".json", StringComparison.Ordinal)) return bytes;
            var text = new System.Text.UTF8Encoding(false).GetString(bytes);
            var pinned = WithoutUnityFrame(text).Replace("\"pluginVersion\": \"" + PluginInfo.Version + "\"", "\"pluginVersion\": \"0.1.0\"");
            return pinned == text ? bytes : new System.Text.UTF8Encoding(false).GetBytes(pinned);
        }

        static string WithoutUnityFrame(string text)
        {
            var start = text.IndexOf("\n  \"" + UnityFrameRecord.Key + "\": {", StringComparison.Ordinal);
            if (start < 0) return text;
            var end = text.IndexOf("\n  },", start, StringComparison.Ordinal) + "\n  },".Length;
            return text.Remove(start, end - start);
        }

        internal static readonly Dictionary<string, string> Expected = new Dictionary<string, string>
        {
            ["blur/dataset_config.json"] = "22825d1e22a3839d45f35c76b29fead9f0442f0878926eb9e057e9b3097d7101",
            ["blur/eval_protocol.json"] = "b80d1317a8b50523752957320142cc11e8bab471cbabe2b8abfaa9d51b9382e8",
            ["blur/labels.json"] = "c9805994b087748ec1b1d089a35c0893b9ec4daabde211f8caf0f5d0b48e8cbc",
            ["blur/labels_preview_test.png"] = "3077b1f7ffb8f4132c34981ef59f9ec28eb71572efacabe995844c1c90f5d6a8",
            ["blur/labels_preview_train.png"] = "51399d7cd5efcf67626214c68d273556f62f295ac86805494196de97324da18b",
            ["blur/labels_preview_val.png"] = "bc6ae87b26e6d66b6a572653b74efe741bd25d1a8b2f112b480b5a922cb2d89f",
            ["blur/rig_preview.png"] = "e655fccf6666eab2d4cf1da26e725a1596f9e42053e5dfa02a65acc643477864",
            ["blur/test/r_0.png"] = "bdfb6d90909d4a81778e101edf1e21969ee905dcc5668f6bf0b8b0e76172a787",
            ["blur/test/r_0_depth_0000.png"] = "b367bf477a1f179e61bc4411a6128950f0b3cf97c2bcece35887747e4b50a5b0",
            ["blur/test/r_0_instance_0000.png"] = "ca1baabdfacf511c7196bf57eb088cf84028388ac235d28dc962d35cafd80951",
            ["blur/test/r_0_mask_0000.png"] = "b9ed2f1822c5a9ad50a7f2156a5ff83c66022e078946804ea19a486452704f55",
            ["blur/test/r_0_normal_0000.png"] = "670f7d2f60cf6aefd52c9bc34cd279b503f52b61b1fb8a83cc33cb4485b21c10",
            ["blur/test/r_0_semantic_0000.png"] = "160277183c077e7186b992966ef7615b2403d63046a6967b309dcb86c2181bf5",
            ["blur/test/r_0_sharp_0000.png"] = "851a2db17149e0fc3e47ca8aeb0e1a052027c1f7fd598c083456f50db89f4c60",
            ["blur/train/r_0.png"] = "48cd9c3fb3270977050d200fce212d1421c5c9d7c3c4813f406ac718531011a0",
            ["blur/train/r_0_clean.png"] = "ba00cfac289e5a7a3b9f7a73baaec579d6661536fcd214bcbde20a04b62a6655",
            ["blur/train/r_0_depth_0000.png"] = "1590b7af3e990b021fca48e4a363fd97cfbbfad3100f37457ec53719018d5634",
            ["blur/train/r_0_instance_0000.png"] = "17e5f9381a2ae9c95c7a6f98b3c63ad59e6fcfe9d218951647bce67836ba407c",
            ["blur/train/r_0_mask_0000.png"] = "a9c66b47f0b87b47416380d45689d744531e7eeded62fbcfe06a42f035e35656",
            ["blur/train/r_0_normal_0000.png"] = "3b729779ec2fab16b7e4d5d9409f6f153a7424dccf3e3709d6f03747235d4882",
            ["blur/train/r_0_semantic_0000.png"] = "e807089491831325f888b5e18da57163839e26a7e381dddbb8b1e9e2b4fd4688",
            ["blur/train/r_0_sharp_0000.png"] = "04c61bef00f4b51ea41c31bd08ae4a6197c55f1e9d1763d449d0ab1529746d66",
            ["blur/train/r_1.png"] = "c92de64981c18c354930e4ff17113342baeb73490810b32407bd9c3f0f66c772",
            ["blur/train/r_1_clean.png"] = "30ceda826418374d3385ba876f6f62518e4da6cf25df3da7233dfee4943d749a",
            ["blur/train/r_1_depth_0000.png"] = "fb11f6fc28cb952e17a44639034c8f3c557dea51386d05060ea011ed518986e3",
            ["blur/train/r_1_instance_0000.png"] = "632f04ceeb3fb31482a425d061bd9787e5567298a647b82762b7c1a8e82fe6f6",
            ["blur/train/r_1_mask_0000.png"] = "0b42dfd52bf56109be14b40497b1f633690fbb081855fcedada6a1640beec902",
            ["blur/train/r_1_normal_0000.png"] = "7fc83fb020652b8836f7320925ef09db33a694c37fcd37ee2283ff172c5bb43f",
            ["blur/train/r_1_semantic_0000.png"] = "a48e9e14a3f4b04c2072e02710dce7a7810d870d3029b6a7266b2ebdfbe903c7",
            ["blur/train/r_1_sharp_0000.png"] = "9e7d4b707e8034141a335462b27dfda328b7752c60ef5d1f2f0423e75a1720f5",
            ["blur/transforms_test.json"] = "06292ea086b9d2cd19398b6f0251f37c411f405e837f498c21e12cfe96305c8f",
            ["blur/transforms_train.json"] = "369d325c251868dad4b54e5c01ebd407da387492fa57867a81a811431a25a698",
            ["blur/transforms_val.json"] = "8762740b803786e868999cd466e5a515b9f9996d3f0e6a302e9a65b681379da5",
            ["blur/val/r_0.png"] = "6d7ef022d103166aa0e54f5e7b3d0179cc53ce0f42cde98849c3cb0269e472b4",
            ["blur/val/r_0_depth_0000.png"] = "6ed0881b01e17a5f8c7e5b0119fae9047be9fd4c84da0ed3afc4b8df73c30173",
            ["blur/val/r_0_instance_0000.png"] = "c2df623ffc96780c0fecd2ccf1c3c9f3bd690e166f37bf91afa4d7fc2ecb7348",
            ["blur/val/r_0_mask_0000.png"] = "0126d270232fdd0f2a36ba7a67363ade42a0aba363f96f2af9b95711974914e5",
            ["blur/val/r_0_normal_0000.png"] = "95be0da0b7d09768e681bdd9f902c5b6e5efed395d71609af5e4a0024b1092ed",
            ["blur/val/r_0_semantic_0000.png"] = "391e76f47862981c49313539d056bdcdfe949bdc36821d78a4deec803747b6e7",
            ["blur/val/r_0_sharp_0000.png"] = "34db49c7ae5b17ba3b3451c8774b0798b7682944f92714545b2712f0bd9feba3",
            ["lens-blur-apart/dataset_config.json"] = "e3010b071f55a70d82593916ffadde1cb06e99586a80484440f4c8d8321d7207",
            ["lens-blur-apart/eval_protocol.json"] = "b80d1317a8b50523752957320142cc11e8bab471cbabe2b8abfaa9d51b9382e8",
            ["lens-blur-apart/labels.json"] = "c9805994b087748ec1b1d089a35c0893b9ec4daabde211f8caf0f5d0b48e8cbc",
            ["lens-blur-apart/labels_preview_test.png"] = "3d368c14b4b8314a3f9631ea656ad0882f4e6cd0108f6513786580e598463a21",
            ["lens-blur-apart/labels_preview_train.png"] = "e7e7068f7b5a5ce5e2eac9a8b94307906d14f628b51683b6e1bd4224ce5edf29",
            ["lens-blur-apart/labels_preview_val.png"] = "21f577fd9a80d158e1d5e206bee403a3da9616153e1eed54bdc1014a704a85a2",
            ["lens-blur-apart/rig_preview.png"] = "e3506216b17d2dfcafa6287ec044dcbbea060d34014d65bc9853ca1d617f1ffa",
            ["lens-blur-apart/test/r_0.png"] = "c418b92858072b18461ffed0ae00a5963003673818d45875d7f05a4b37030a37",
            ["lens-blur-apart/test/r_0_depth_0000.png"] = "2298719712883c04ed2d65820c98550de72a05fc31e7bc8220fa3b844b94c02a",
            ["lens-blur-apart/test/r_0_instance_0000.png"] = "480a42029aad2f57763b6ccdc8ac15eaadaff30c75083ef5ab72de5fb3c3f23a",
            ["lens-blur-apart/test/r_0_mask_0000.png"] = "c6d99fc5e431ca24e8c6240d0640509d7521289ec81967ba49a5b2ece0f7290c",
            ["lens-blur-apart/test/r_0_normal_0000.png"] = "774c08202d6c0045001e46bddf12a6eda3d925dfa9e611d6f35dcb01f7d6e41b",
            ["lens-blur-apart/test/r_0_semantic_0000.png"] = "0af9f6d83636b0b8e6b2ddb500a95f0b1cddc0b580324eeca39ae4cf7141b4a5",
            ["lens-blur-apart/test/r_0_sharp_0000.png"] = "96fcc24faf9ffd42482c986007c1f6f2986f67d1a388116d5449b508f68ac7fa",
            ["lens-blur-apart/train/r_0.png"] = "cef1df80e4acb77a7071bc53776fcaabd7a1beb3f49e48b3e72e2c4c948eb218",
            ["lens-blur-apart/train/r_0_clean.png"] = "14fa24018b92e193489eb1c81122b455f6856203d44655580d7dd0eff94e789b",
            ["lens-blur-apart/train/r_0_depth_0000.png"] = "34a7fec41278e48d7c78f9096de4291d5b3eb4e35db4f5bb8d1e9202685d2630",
            ["lens-blur-apart/train/r_0_instance_0000.png"] = "21f1e9f0ca9c26817ec2250243774b079d1145cb1f18b9fec31f623d9cdb15a6",
            ["lens-blur-apart/train/r_0_mask_0000.png"] = "79a5f070d61d5dcf1b77651fefba239829a240ecbea6ab5a1880446c1d6b874c",
            ["lens-blur-apart/train/r_0_normal_0000.png"] = "05c18d9a5342f03ceb58c3a990b9d8831d409b028837043c4a3683f36bcc8f34",
            ["lens-blur-apart/train/r_0_semantic_0000.png"] = "ce07c00dfd093e9d68f8d721de7f98f9c8d6480cf7214a4428715718734eff23",
            ["lens-blur-apart/train/r_0_sharp_0000.png"] = "09e679316262bda1f7b56031823bed53885e829493b397fbc99468420a2fd0bc",
            ["lens-blur-apart/train/r_1.png"] = "7f036982466f2f258dc5f5dc4f6513ff7d48ce78ae536e03d16763f83ff1bba5",
            ["lens-blur-apart/train/r_1_clean.png"] = "2164062a83450c6627ba9902677cbdfb54cf8c2a34d35df967fc3b94a814d534",
            ["lens-blur-apart/train/r_1_depth_0000.png"] = "02d9d00ca40b15b22ab186f575dc5c6f8293c7d56aaf1764f140f26151db6e0d",
            ["lens-blur-apart/train/r_1_instance_0000.png"] = "776a0d70dada3b0768cb338144ea730d2af727c2f1c50b176b740141b70135f2",
            ["lens-blur-apart/train/r_1_mask_0000.png"] = "694d5e65b9f9d1dff2aabcf4cbd020109a6781468d04e539db302651e911754b",
            ["lens-blur-apart/train/r_1_normal_0000.png"] = "f81a67be27598fda565827dc079f2aa9183b4f7ba45dcdbd650fd27d8cf0add2",
            ["lens-blur-apart/train/r_1_semantic_0000.png"] = "2ce2af30534e260675a3cae0a690121bfbc37b1366c6781c9802bbec07025358",
            ["lens-blur-apart/train/r_1_sharp_0000.png"] = "c3c80cc8e5c55ad8c9c6974cef5d6c240f1d941b362ecbb5da41f4550774b18e",
            ["lens-blur-apart/transforms_test.json"] = "168f7eccb783278e1389c6b55d902735d8133bc524acba1fba0903469bb0b274",
            ["lens-blur-apart/transforms_train.json"] = "509a93d4c25c4579cd722cd14b4b6bc984ab98425883e3ec311308aa9ad99647",
            ["lens-blur-apart/transforms_val.json"] = "68fdb909d2e4bfb6e64ba29b564a9d6c4d69f34cc6001e2f467a6913c745ea99",
            ["lens-blur-apart/val/r_0.png"] = "fd8f04d03c0836b38494136c21312b4fb9e4bf82d947201feacc454f34fdf94a",
            ["lens-blur-apart/val/r_0_depth_0000.png"] = "2115c044e9b3157f78eaa27eccf6f7efebb034ac3e85c98b1129fbff8bc748aa",
            ["lens-blur-apart/val/r_0_instance_0000.png"] = "abcb2891ced32a2f02f01782f948b97db34ffeaaad4b24dbd144c5d5c6d63e66",
            ["lens-blur-apart/val/r_0_mask_0000.png"] = "bdbc08c144e752e97e63e8ca426f2424b55ccc2056dc440705ac40a3c2764b5e",
            ["lens-blur-apart/val/r_0_normal_0000.png"] = "0274925fc5ac6d06b7d6bda60336db9c6feeeba49904418b7cab0c42f73e39af",
            ["lens-blur-apart/val/r_0_semantic_0000.png"] = "53c19a423f06ff14ec2757e9ae8be83f64b9e93fc9b57810e9cefa48662e5770",
            ["lens-blur-apart/val/r_0_sharp_0000.png"] = "fbb3041e2032b58966a89e4777abc04bcf163cac0e0f30706f134b80f8a4d8d8",
            ["lens-blur-shared/dataset_config.json"] = "74fb739494f11e358d35c0014b00b050f792ed6bf33fe58dd0b7d58e54e52869",
            ["lens-blur-shared/eval_protocol.json"] = "b80d1317a8b50523752957320142cc11e8bab471cbabe2b8abfaa9d51b9382e8",
            ["lens-blur-shared/labels.json"] = "c9805994b087748ec1b1d089a35c0893b9ec4daabde211f8caf0f5d0b48e8cbc",
            ["lens-blur-shared/labels_preview_test.png"] = "3d368c14b4b8314a3f9631ea656ad0882f4e6cd0108f6513786580e598463a21",
            ["lens-blur-shared/labels_preview_train.png"] = "e7e7068f7b5a5ce5e2eac9a8b94307906d14f628b51683b6e1bd4224ce5edf29",
            ["lens-blur-shared/labels_preview_val.png"] = "21f577fd9a80d158e1d5e206bee403a3da9616153e1eed54bdc1014a704a85a2",
            ["lens-blur-shared/rig_preview.png"] = "e3506216b17d2dfcafa6287ec044dcbbea060d34014d65bc9853ca1d617f1ffa",
            ["lens-blur-shared/test/r_0.png"] = "c418b92858072b18461ffed0ae00a5963003673818d45875d7f05a4b37030a37",
            ["lens-blur-shared/test/r_0_depth_0000.png"] = "d1d5d38231b9b70bc100a62d26cd00c33f9dd40096281bb40ac4dae7490245ad",
            ["lens-blur-shared/test/r_0_instance_0000.png"] = "480a42029aad2f57763b6ccdc8ac15eaadaff30c75083ef5ab72de5fb3c3f23a",
            ["lens-blur-shared/test/r_0_mask_0000.png"] = "c6d99fc5e431ca24e8c6240d0640509d7521289ec81967ba49a5b2ece0f7290c",
            ["lens-blur-shared/test/r_0_normal_0000.png"] = "7af7b4b35d1077ba27d574686ffc7526495cf67b0f087e7edaaa2fc1d45eef63",
            ["lens-blur-shared/test/r_0_semantic_0000.png"] = "0af9f6d83636b0b8e6b2ddb500a95f0b1cddc0b580324eeca39ae4cf7141b4a5",
            ["lens-blur-shared/test/r_0_sharp_0000.png"] = "96fcc24faf9ffd42482c986007c1f6f2986f67d1a388116d5449b508f68ac7fa",
            ["lens-blur-shared/train/r_0.png"] = "cef1df80e4acb77a7071bc53776fcaabd7a1beb3f49e48b3e72e2c4c948eb218",
            ["lens-blur-shared/train/r_0_clean.png"] = "14fa24018b92e193489eb1c81122b455f6856203d44655580d7dd0eff94e789b",
            ["lens-blur-shared/train/r_0_depth_0000.png"] = "99c7daa2ebcc9cff3d858edf5500586e39900c0dfbeb7b59612761dc97e96ec4",
            ["lens-blur-shared/train/r_0_instance_0000.png"] = "21f1e9f0ca9c26817ec2250243774b079d1145cb1f18b9fec31f623d9cdb15a6",
            ["lens-blur-shared/train/r_0_mask_0000.png"] = "79a5f070d61d5dcf1b77651fefba239829a240ecbea6ab5a1880446c1d6b874c",
            ["lens-blur-shared/train/r_0_normal_0000.png"] = "2569ccaa705f9d088aa4fde26ed759853b5ac9c96a11a345895f9bd736926e20",
            ["lens-blur-shared/train/r_0_semantic_0000.png"] = "ce07c00dfd093e9d68f8d721de7f98f9c8d6480cf7214a4428715718734eff23",
            ["lens-blur-shared/train/r_0_sharp_0000.png"] = "09e679316262bda1f7b56031823bed53885e829493b397fbc99468420a2fd0bc",
            ["lens-blur-shared/train/r_1.png"] = "7f036982466f2f258dc5f5dc4f6513ff7d48ce78ae536e03d16763f83ff1bba5",
            ["lens-blur-shared/train/r_1_clean.png"] = "2164062a83450c6627ba9902677cbdfb54cf8c2a34d35df967fc3b94a814d534",
            ["lens-blur-shared/train/r_1_depth_0000.png"] = "f07254c2841fe072459fa482dfa9f75eedee826d8160ae524880567e279f0492",
            ["lens-blur-shared/train/r_1_instance_0000.png"] = "776a0d70dada3b0768cb338144ea730d2af727c2f1c50b176b740141b70135f2",
            ["lens-blur-shared/train/r_1_mask_0000.png"] = "694d5e65b9f9d1dff2aabcf4cbd020109a6781468d04e539db302651e911754b",
            ["lens-blur-shared/train/r_1_normal_0000.png"] = "4a768c6b41676418155921068c988f1e3a77ca38a5c87ae4ea3d1f517bc2bce0",
            ["lens-blur-shared/train/r_1_semantic_0000.png"] = "2ce2af30534e260675a3cae0a690121bfbc37b1366c6781c9802bbec07025358",
            ["lens-blur-shared/train/r_1_sharp_0000.png"] = "c3c80cc8e5c55ad8c9c6974cef5d6c240f1d941b362ecbb5da41f4550774b18e",
            ["lens-blur-shared/transforms_test.json"] = "168f7eccb783278e1389c6b55d902735d8133bc524acba1fba0903469bb0b274",
            ["lens-blur-shared/transforms_train.json"] = "509a93d4c25c4579cd722cd14b4b6bc984ab98425883e3ec311308aa9ad99647",
            ["lens-blur-shared/transforms_val.json"] = "68fdb909d2e4bfb6e64ba29b564a9d6c4d69f34cc6001e2f467a6913c745ea99",
            ["lens-blur-shared/val/r_0.png"] = "fd8f04d03c0836b38494136c21312b4fb9e4bf82d947201feacc454f34fdf94a",
            ["lens-blur-shared/val/r_0_depth_0000.png"] = "f095f348e4b010bd94136967b9e62b4d45ae1dd93954dfbca1eebe02a13a0a2e",
            ["lens-blur-shared/val/r_0_instance_0000.png"] = "abcb2891ced32a2f02f01782f948b97db34ffeaaad4b24dbd144c5d5c6d63e66",
            ["lens-blur-shared/val/r_0_mask_0000.png"] = "bdbc08c144e752e97e63e8ca426f2424b55ccc2056dc440705ac40a3c2764b5e",
            ["lens-blur-shared/val/r_0_normal_0000.png"] = "1d50a87ea87d1fe8e1583a6000cc359f0d869f2ade9d62351a48a20adfcb0456",
            ["lens-blur-shared/val/r_0_semantic_0000.png"] = "53c19a423f06ff14ec2757e9ae8be83f64b9e93fc9b57810e9cefa48662e5770",
            ["lens-blur-shared/val/r_0_sharp_0000.png"] = "fbb3041e2032b58966a89e4777abc04bcf163cac0e0f30706f134b80f8a4d8d8",
            ["lens-sharp/dataset_config.json"] = "34abf93f3623f92e073bcf3af2c24b7877111f9b2035123bef90448aec9c0c4c",
            ["lens-sharp/eval_protocol.json"] = "b80d1317a8b50523752957320142cc11e8bab471cbabe2b8abfaa9d51b9382e8",
            ["lens-sharp/labels.json"] = "c9805994b087748ec1b1d089a35c0893b9ec4daabde211f8caf0f5d0b48e8cbc",
            ["lens-sharp/labels_preview_test.png"] = "3d368c14b4b8314a3f9631ea656ad0882f4e6cd0108f6513786580e598463a21",
            ["lens-sharp/labels_preview_train.png"] = "e7e7068f7b5a5ce5e2eac9a8b94307906d14f628b51683b6e1bd4224ce5edf29",
            ["lens-sharp/labels_preview_val.png"] = "21f577fd9a80d158e1d5e206bee403a3da9616153e1eed54bdc1014a704a85a2",
            ["lens-sharp/rig_preview.png"] = "e3506216b17d2dfcafa6287ec044dcbbea060d34014d65bc9853ca1d617f1ffa",
            ["lens-sharp/test/r_0.png"] = "96fcc24faf9ffd42482c986007c1f6f2986f67d1a388116d5449b508f68ac7fa",
            ["lens-sharp/test/r_0_depth_0000.png"] = "2298719712883c04ed2d65820c98550de72a05fc31e7bc8220fa3b844b94c02a",
            ["lens-sharp/test/r_0_instance_0000.png"] = "480a42029aad2f57763b6ccdc8ac15eaadaff30c75083ef5ab72de5fb3c3f23a",
            ["lens-sharp/test/r_0_mask_0000.png"] = "c6d99fc5e431ca24e8c6240d0640509d7521289ec81967ba49a5b2ece0f7290c",
            ["lens-sharp/test/r_0_normal_0000.png"] = "774c08202d6c0045001e46bddf12a6eda3d925dfa9e611d6f35dcb01f7d6e41b",
            ["lens-sharp/test/r_0_semantic_0000.png"] = "0af9f6d83636b0b8e6b2ddb500a95f0b1cddc0b580324eeca39ae4cf7141b4a5",
            ["lens-sharp/train/r_0.png"] = "9c64fe707c18c9e28d7cfae0e00c88361a3c879753f3086b3036263bc1f6c635",
            ["lens-sharp/train/r_0_clean.png"] = "3db69209aea38c34788605ba8a2aa62cbcc674e14a4c292775907a33810df850",
            ["lens-sharp/train/r_0_depth_0000.png"] = "34a7fec41278e48d7c78f9096de4291d5b3eb4e35db4f5bb8d1e9202685d2630",
            ["lens-sharp/train/r_0_instance_0000.png"] = "21f1e9f0ca9c26817ec2250243774b079d1145cb1f18b9fec31f623d9cdb15a6",
            ["lens-sharp/train/r_0_mask_0000.png"] = "79a5f070d61d5dcf1b77651fefba239829a240ecbea6ab5a1880446c1d6b874c",
            ["lens-sharp/train/r_0_normal_0000.png"] = "05c18d9a5342f03ceb58c3a990b9d8831d409b028837043c4a3683f36bcc8f34",
            ["lens-sharp/train/r_0_semantic_0000.png"] = "ce07c00dfd093e9d68f8d721de7f98f9c8d6480cf7214a4428715718734eff23",
            ["lens-sharp/train/r_1.png"] = "c9b2933e763d2e57f3cd7f9e9397236370fa02d4a0bbf1557eba7cc7f7f67621",
            ["lens-sharp/train/r_1_clean.png"] = "246274f23de1f94c4c06dafcf354c20ccf4a4aebddafb9a47b74ee1e035ad90d",
            ["lens-sharp/train/r_1_depth_0000.png"] = "02d9d00ca40b15b22ab186f575dc5c6f8293c7d56aaf1764f140f26151db6e0d",
            ["lens-sharp/train/r_1_instance_0000.png"] = "776a0d70dada3b0768cb338144ea730d2af727c2f1c50b176b740141b70135f2",
            ["lens-sharp/train/r_1_mask_0000.png"] = "694d5e65b9f9d1dff2aabcf4cbd020109a6781468d04e539db302651e911754b",
            ["lens-sharp/train/r_1_normal_0000.png"] = "f81a67be27598fda565827dc079f2aa9183b4f7ba45dcdbd650fd27d8cf0add2",
            ["lens-sharp/train/r_1_semantic_0000.png"] = "2ce2af30534e260675a3cae0a690121bfbc37b1366c6781c9802bbec07025358",
            ["lens-sharp/transforms_test.json"] = "43efbcbbada4cc55c78ad55c0692b222a02123d56b5e0410e5767fa38e0d4682",
            ["lens-sharp/transforms_train.json"] = "fb56777e2a28529a082e3f25bd654331ce863615dff82cb76cba17b6b9a4e1dd",
            ["lens-sharp/transforms_val.json"] = "ee9a68b7e36a4735b2894ca7878ca22221af721283fda137e8159c1f10eaa6e6",
            ["lens-sharp/val/r_0.png"] = "fbb3041e2032b58966a89e4777abc04bcf163cac0e0f30706f134b80f8a4d8d8",
            ["lens-sharp/val/r_0_depth_0000.png"] = "2115c044e9b3157f78eaa27eccf6f7efebb034ac3e85c98b1129fbff8bc748aa",
            ["lens-sharp/val/r_0_instance_0000.png"] = "abcb2891ced32a2f02f01782f948b97db34ffeaaad4b24dbd144c5d5c6d63e66",
            ["lens-sharp/val/r_0_mask_0000.png"] = "bdbc08c144e752e97e63e8ca426f2424b55ccc2056dc440705ac40a3c2764b5e",
            ["lens-sharp/val/r_0_normal_0000.png"] = "0274925fc5ac6d06b7d6bda60336db9c6feeeba49904418b7cab0c42f73e39af",
            ["lens-sharp/val/r_0_semantic_0000.png"] = "53c19a423f06ff14ec2757e9ae8be83f64b9e93fc9b57810e9cefa48662e5770",
        };
    }
}
