using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Everything a plan writes — its text form, the three transforms files, dataset_config.json, the rig preview PLY
    /// and picture, its warnings, and a shard's share — is byte for byte what it was before plans made their views on
    /// demand (PlannedViewList). The expected SHA-256 sums were taken from the previous code (commit 86d847a, which held
    /// every view in a list) running this very test; a sum that changes means an output changed.
    /// </summary>
    [TestFixture]
    public class PlanOutputsUnchangedTests
    {
        static readonly Provenance Fixed = new Provenance(new DateTime(2026, 11, 27, 12, 0, 0, DateTimeKind.Utc), null, "test", imagesRendered: false);

        static DatasetSettings Read(string json)
        {
            var read = DatasetSettingsJson.Read(json);
            Assert.That(read.Warnings, Is.Empty, string.Join("\n", read.Warnings));
            return read.Settings;
        }

        static IEnumerable<TestCaseData> Configs()
        {
            yield return new TestCaseData("default", Read("{ \"splits\": { \"train\": { \"count\": 400 }, \"val\": { \"count\": 300 }, \"test\": { \"count\": 200 } } }"),
                new PlanTarget(new Vector3d(1, 2, 3), 0.5));
            yield return new TestCaseData("formations", Read(@"{ ""seed"": 11, ""normalisation"": ""nerf-synthetic"", ""distance"": 5,
                ""splits"": {
                  ""train"": { ""count"": 333, ""formation"": { ""kind"": ""halo"", ""elevationDegrees"": 20, ""startAzimuthDegrees"": 15 }, ""depth"": ""png"" },
                  ""val"": { ""count"": 250, ""formation"": { ""kind"": ""sphere"" }, ""mask"": true },
                  ""test"": { ""count"": 199, ""formation"": { ""kind"": ""semisphere"", ""topElevationDegrees"": 70, ""bottomElevationDegrees"": -10, ""spiralRatio"": 0.37 } } } }"),
                new PlanTarget(new Vector3d(-2, 0.5, 1), 1.5));
            yield return new TestCaseData("random-orbit-fit", Read(@"{ ""seed"": -5, ""normalisation"": ""fit-radius"", ""normalisedTargetRadius"": 0.8, ""width"": 640, ""height"": 360,
                ""splits"": {
                  ""train"": { ""count"": 500, ""formation"": { ""kind"": ""random"", ""upperHemisphereOnly"": false }, ""normal"": ""png"" },
                  ""val"": { ""count"": 0 },
                  ""test"": { ""count"": 120, ""formation"": { ""kind"": ""orbit"", ""turns"": 3, ""lowElevationDegrees"": -20, ""highElevationDegrees"": 60, ""startAzimuthDegrees"": 45 } } },
                ""loaders"": [""3dgs""] }"),
                new PlanTarget(new Vector3d(0, 1, 0), 1));
            yield return new TestCaseData("range-warnings", Read(@"{ ""seed"": 9, ""distance"": 1.8, ""normalisation"": ""none"",
                ""splits"": { ""train"": { ""count"": 300, ""depth"": ""png"", ""mask"": true }, ""val"": { ""count"": 30 }, ""test"": { ""count"": 60 } } }"),
                new PlanTarget(new Vector3d(3, 1, -2), 0.6));
            yield return new TestCaseData("imported", Read(@"{ ""seed"": 2, ""splits"": { ""train"": { ""count"": 80 }, ""val"": { ""count"": 10 },
                ""test"": { ""source"": { ""kind"": ""imported"", ""path"": """ + Fixtures.LegoTrainPath.Replace("\\", "\\\\") + @""", ""useFileIntrinsics"": true } } } }"),
                PlanTarget.Headless);
            yield return new TestCaseData("imported-recentred", Read(@"{ ""normalisation"": ""none"", ""splits"": {
                ""train"": { ""source"": { ""kind"": ""imported"", ""path"": """ + Fixtures.LegoTrainPath.Replace("\\", "\\\\") + @""" } }, ""val"": { ""count"": 5 }, ""test"": { ""count"": 7 } } }"),
                new PlanTarget(new Vector3d(0.5, 0, -0.25), 0.7));
            yield return new TestCaseData("monocular", Read(@"{ ""seed"": 3, ""loaders"": [""nerf""], ""splits"": { ""train"": { ""count"": 40 }, ""val"": { ""count"": 7 }, ""test"": { ""count"": 9 } },
                ""time"": { ""mode"": ""monocular"", ""start"": 0.5, ""end"": 2.5 } }"),
                PlanTarget.Headless);
            yield return new TestCaseData("multi-view", Read(@"{ ""seed"": 4, ""loaders"": [""3dgs""], ""splits"": { ""train"": { ""count"": 12 }, ""val"": { ""count"": 2 }, ""test"": { ""count"": 3 } },
                ""time"": { ""mode"": ""multi-view"", ""start"": 0, ""end"": 1, ""steps"": 9 } }"),
                PlanTarget.Headless);
        }

        static IEnumerable<TestCaseData> Cases() => Configs().Select(c => new TestCaseData(c.Arguments[0], c.Arguments[1], c.Arguments[2]).SetName("PlanOutputsUnchanged_" + c.Arguments[0]));

        static readonly Dictionary<string, string> Expected = new Dictionary<string, string>
        {
            ["range-warnings/config"] = "58c341f45ede7da46ab3fddaf0d15370dd96c0e126634761069338a0f56bd212",
            ["range-warnings/plan"] = "aeda997640a248515e8886984ead7ee5b912e9b01ea06a4e12a2d8d526e37f76",
            ["range-warnings/ply"] = "d82300ed90093080d724bf2d914ef840600efed795b0dbe2affc7e18f1bb8fb0",
            ["range-warnings/png"] = "1cb751305a300d6dcd9a23a16d38aded2532dda1a3789ec336ea5b84867f6644",
            ["range-warnings/shard"] = "a17022f63a9093a2b602895725740e4961617cd723b88dad1de5f88c9e946e13",
            ["range-warnings/shard_transforms_test"] = "aea3663f07c6957ebbe057db2c4b34919334043e63247994ebd7a483ae1f3252",
            ["range-warnings/shard_transforms_train"] = "1321559315a9a2ef9ee2d4031cccd791ba75c5b5fe052b10cbaee24fbb5a79ba",
            ["range-warnings/shard_transforms_val"] = "d661030e8d96cdeb4d77051c8e87378f76d19d1dee013dec81a168e7e347849b",
            ["range-warnings/transforms_test"] = "0304b2697db89ced0c9f76ed20eb6bf301f97c991dd475e1a66ef7713787b556",
            ["range-warnings/transforms_train"] = "638f0a9aa638ce43ed9b84391684c6a69cfc2a75d22a18c14ece9d7c7805f1cc",
            ["range-warnings/transforms_val"] = "b03173e5df929906a607eb2e97faf19276b22b3c53825058fd9c8c22df7c8665",
            ["range-warnings/warnings"] = "43aa269bb567cf60c5b179392b5965b7fd6dd77346f2d8a54cc763f27a167a6c",
            ["default/config"] = "8555bd80a49f16331f1f9978460d31e611189b5ee8a15abc7a4e81047a34dad6",
            ["default/plan"] = "a8257851c7b5e02b055e621d0d031ec0b8211f7037636f32565efd92a5c3ecd2",
            ["default/ply"] = "936d4e4c3ea0a25db71a227e791288bc3896c772de2395f0b69946141b4d6b8b",
            ["default/png"] = "6f990a12c90fac9fa76f9d3294a731e6d55ade96903e4e1fa6cb3039940928f6",
            ["default/shard"] = "43a11b74b20ba09a90bd49c6c8fb508d6189247f1e31f20b608417562a2ebc3f",
            ["default/shard_transforms_test"] = "370a8074e480034155b74ed6bfb629edd3323a88259f7d829f842f4fc5ae2735",
            ["default/shard_transforms_train"] = "aeb0293bf20099ac69207cce4cd9d159da33542bf481ea3b18468bcd6fa9e4d8",
            ["default/shard_transforms_val"] = "23fa3441c632a54392a690634032f4be974b97b521af090e8216c092eac63db7",
            ["default/transforms_test"] = "e25f7717ec907097fd4eb88c35f686ba60bc25b439e553ea879de1093e482f4a",
            ["default/transforms_train"] = "fa641a02f5825c206249b21cce4fdef433f9f048b612fb8a15b4891cdaaf3f3d",
            ["default/transforms_val"] = "b77803914c0aeb987978e10991e852ad3e2f88be4cdbcbe736772a1944022a7c",
            ["default/warnings"] = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855",
            ["formations/config"] = "b2eadff403ff10a855cfa849d39f6a7612c7a9873700dcb758b3e6ee23513bc6",
            ["formations/plan"] = "a04b529be1f11d987767e3bbbf2a276956614ba63ec8d10b720489ac68114bd5",
            ["formations/ply"] = "bce37d4d5c3c3302dfe985f0c831b515c7f16b212ebca5d6f06f2d18fef93b13",
            ["formations/png"] = "8f822581fc403a83574101177901127f41a907c2b1e91135e3e2ae57f1bbd6a8",
            ["formations/shard"] = "836232a95ee33c57a188cb81250a2941ada1c7a8d9c3c3df35162d8cf31af3fc",
            ["formations/shard_transforms_test"] = "cb414995993f4a7d4a02d2a77cef2956603838e631371a485e50dfc055749de3",
            ["formations/shard_transforms_train"] = "fd59b1000d4733e91bb5dc471375d6084190c7689ef971bdccae745a4483edd9",
            ["formations/shard_transforms_val"] = "0c9be9db7c519a909eb11e815f9d5149ceaa305831845752cdba4ef6955e1627",
            ["formations/transforms_test"] = "99967899c27b5361a03a8dca46b3c42feafcdab6eb2b854d31015cc9d95b79b7",
            ["formations/transforms_train"] = "820cdd0ee6c97e1d64cb669868561c12d2dad239681278ef1d2255cb6752ab6a",
            ["formations/transforms_val"] = "2e62d4c2542eef22f62992b65edfb57d9029b825e067e4af1eaa33493616d3a2",
            ["formations/warnings"] = "e43ed79231f19e3d2d8a81310d04d8961863418d8c416fdd896889a07a8ce922",
            ["imported-recentred/config"] = "31e77f5bed1c19cb2490a1696f4f098989c867933163384cae1b3b9c70a5aa45",
            ["imported-recentred/plan"] = "cf5eeb8c1b836830db06dbabbb3488e72df3b8b5c76d35b6172ed91185411c52",
            ["imported-recentred/ply"] = "1b0a4d66ada34439519c4ff2db9406f46dedbcf935296354663bddcd3d8b0009",
            ["imported-recentred/png"] = "a6536673c2954dc472b26e9e9d151785bacc905d34887ce4b7a1760a06e5d953",
            ["imported-recentred/shard"] = "11e85857b7e8e5bfc3bfe1944d60ce90dee6e1114dc3d1a91f2d00b331026162",
            ["imported-recentred/shard_transforms_test"] = "0be8a9650c7921f50c80944809603942275315887bebcab30ee8d6848ff7d200",
            ["imported-recentred/shard_transforms_train"] = "b879c4e944890c92bbdf9e6158df587f8f806be16e11f49c87164dcccf79ab10",
            ["imported-recentred/shard_transforms_val"] = "34399792c1b06ee28bf923bf9ce7f5a76ff24e9fda4a3f4f61509a52b0d713ab",
            ["imported-recentred/transforms_test"] = "d93d5b5d53935910a10f43879b03288991322e42a0dbd63e8330972b9297061a",
            ["imported-recentred/transforms_train"] = "e763a70d15bf5fa0c5bf6087813e4d7b8f60786dd8af0ac9b21c6e7776c48f39",
            ["imported-recentred/transforms_val"] = "1db36411211d34c0205e1301dff05bb0b29f7c9ca5b44a1da0e30f789734b5e7",
            ["imported-recentred/warnings"] = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855",
            ["imported/config"] = "0e9453d0e058906dbca4d1a56b6716807addc3ef812db23f6e6abd26badfa78f",
            ["imported/plan"] = "92014ababe94924fa35829909f7f026bdb0e52975ca7eac5fab95a1a253f3dbf",
            ["imported/ply"] = "860ca490f6400ba8f97eefe2b5eb6341d917298d2c9ac9af6baebe30f743a310",
            ["imported/png"] = "82b56cf63a25f76885ae57fca23dbc26440a4d251d86d9f084e7021976c996cb",
            ["imported/shard"] = "b788cc8611c143ec8af7d7adc8b53d36c3a90492611ac014260c5d7d78d60e5b",
            ["imported/shard_transforms_test"] = "7c606b6756aca527f4063017b7b4f9958b0f066e59b2bb207859150ef63091ec",
            ["imported/shard_transforms_train"] = "af8ad12592646c4424c8e871fc8683ee2863fbd634d33fc65960cdf63a0bf464",
            ["imported/shard_transforms_val"] = "25adab4b49b61b661cc7ec65984f7dc081856fa298f9ca825ea708b6996ce58d",
            ["imported/transforms_test"] = "0a8ffeea8ff26377a210f5d5f804f404787fa69a17d1dd94d69faac5f9fc6d4e",
            ["imported/transforms_train"] = "265138389c005c79b674fd96f3318c897d5a27fc185a197c2e2a0cdd6e28a5c0",
            ["imported/transforms_val"] = "e8e0b259dabb5303303fd4edb14f3093fe65b13c2e671a40e928f4d058848083",
            ["imported/warnings"] = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855",
            ["monocular/config"] = "c0a6aa9dc1c73d18e5eeb3f62f148979b51acf012f1df9d1af8645bbb902c430",
            ["monocular/plan"] = "894395f522317831bdbcaaf3be84505472284f8e128b28dc43ffe376674e81a7",
            ["monocular/ply"] = "98a0304f04bd0c2f99fb4b0235e2b2ae163f89c114f3f1073aae9388ec199fa1",
            ["monocular/png"] = "796b17c0289692803d4381fedbf9efe40659cbdadd67610108c67068b6e345df",
            ["monocular/shard"] = "8edcc45b1d2c61d91ea437ae71c4eb8abb15a7cb2698a4d9d75d1a9be847b442",
            ["monocular/shard_transforms_test"] = "c546aa1c09c13763eda644d832fb9c7ba1f7497837af10020e872144bc11b7da",
            ["monocular/shard_transforms_train"] = "fdd63bd7e8501549690950ac0372be4e4b42d57e9109df92366a03af0530231d",
            ["monocular/shard_transforms_val"] = "02bd07b42a762a85e6ef8a4f04f9964e1fc2df4ee4b4c62175a1753e602fee04",
            ["monocular/transforms_test"] = "41e152e7c569bd4dafeb0ab4a8c8b338b3e7574aabe6b74604e3472fdc38b1da",
            ["monocular/transforms_train"] = "bbcfeaca4933990c725849c7c8f6c334adc051c7affd22e28c6fe438a77f73f4",
            ["monocular/transforms_val"] = "edc163395955bc4fde1b879b3e7020dc1d6c99e94b6c46a485902b5734456ec3",
            ["monocular/warnings"] = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855",
            ["multi-view/config"] = "baaa97f16639677cbb5fe1aea49233101640f731af5777a7ecac4670ff77a12b",
            ["multi-view/plan"] = "f7e6fed3e964ac523d2317a88e95340edb276e350df843de1a71c5d75a33c484",
            ["multi-view/ply"] = "4c4ab7e201531b43f6af5ae5d8c5374b17aa4fbe6287d90fc6b7f8e8ea58c5f2",
            ["multi-view/png"] = "63321af78ed087c51f1f49c7ea46741fc4d33af10f2103399c1c9eb03f455e4b",
            ["multi-view/shard"] = "8d5af112d1f15b0ef1e8bd513de999baca3968230e6d202e57510bfac63534d5",
            ["multi-view/shard_transforms_test"] = "dc242f45ea68f73cf6542cbcac0a3ce6ededd9f49ee29e2ae6acd8b8355be4e2",
            ["multi-view/shard_transforms_train"] = "4cf7d9385728631216cb219b0a03d4e53a4d808a21d67129b2999e4145050c5b",
            ["multi-view/shard_transforms_val"] = "c02fb593436939d29aa872f9b47bb024249b5867096102227b3b877672149ee3",
            ["multi-view/transforms_test"] = "26b4d0798209d9a36af5ca4401d7011f3f31a55eabe9d1b626d1824d4ef1b4d7",
            ["multi-view/transforms_train"] = "84071682e853307fc77012ca7858ffc7f13082bcf7ef1a366667cfddf9dc9f20",
            ["multi-view/transforms_val"] = "b2432511c0b4d6a32a3d5823a2bbb1b1af97b52de7da5e623755fa9074f6759d",
            ["multi-view/warnings"] = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855",
            ["random-orbit-fit/config"] = "ad2ace00ebb6a908fee62337f08762cda2ea5bd0750f7c4e88364c7fa486229c",
            ["random-orbit-fit/plan"] = "1bfaefa9ac5c4dfca156c5b0c31104d00cb4d40daa5f2ef160aff2150f5cb1f2",
            ["random-orbit-fit/ply"] = "dd7ddb0cafd58a9083080b15b23e1d5625396b302f5277b555a4667702ef0ef4",
            ["random-orbit-fit/png"] = "0db6d3f5fee5d139872a6f18b46f9906ad31e8f93feaf8b72f829bdc9ed422d8",
            ["random-orbit-fit/shard"] = "53a2a32943cfb6e721becedcdf39a04b8777676651ffb258bf99b315fa019d44",
            ["random-orbit-fit/shard_transforms_test"] = "3aafb77ac70a08429216c38611266938d98f1f6eeaeb7bfe7bd9c8715160c168",
            ["random-orbit-fit/shard_transforms_train"] = "929507b48432172fc723a759d1cc4a45cde2637a826cfefa180e46e79625dfdd",
            ["random-orbit-fit/shard_transforms_val"] = "61b56ca45251e937753bf934d0557c7bba6fd681db9ad4f2de0a089d1ebe7eff",
            ["random-orbit-fit/transforms_test"] = "b84e65f1db99ce730b103b4aec0b5c2d3abdf756d38afdaa3dd73f0828a7c85a",
            ["random-orbit-fit/transforms_train"] = "51f6361de6e24798c9c3100d75bd393062cf4e90cd61b0a145c599adbd6c043d",
            ["random-orbit-fit/transforms_val"] = "61b56ca45251e937753bf934d0557c7bba6fd681db9ad4f2de0a089d1ebe7eff",
            ["random-orbit-fit/warnings"] = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855",
        };

        [TestCaseSource(nameof(Cases))]
        public void PlanOutputsUnchanged(string name, DatasetSettings settings, PlanTarget target)
        {
            var plan = CapturePlan.Build(settings, target);
            var shard = plan.Only(v => (v.Index + (int)v.Split) % 3 == 1);
            var outputs = new List<(string, byte[])>
            {
                ("plan", Utf8(CapturePlanJson.Write(plan))),
                ("config", Utf8(WithoutUnityFrame(WithoutFixturePath(DatasetConfig.Write(plan, Fixed))))),
                ("ply", RigPreviewPly.Encode(plan)),
                ("png", RigPreviewPicture.Encode(plan)),
                ("warnings", Utf8(string.Join("\n", plan.Warnings.Select(w => w.ToString())))),
                ("shard", Utf8(CapturePlanJson.Write(shard))),
            };
            foreach (var split in DatasetSplits.All)
            {
                outputs.Add(("transforms_" + DatasetSplits.Name(split), Utf8(BlenderTransformsWriter.Write(plan, split))));
                outputs.Add(("shard_transforms_" + DatasetSplits.Name(split), Utf8(BlenderTransformsWriter.Write(shard, split))));
                using (var text = new StringWriter())
                {
                    BlenderTransformsWriter.Write(plan, split, text); // the streamed form the tool writes
                    Assert.That(text.ToString(), Is.EqualTo(BlenderTransformsWriter.Write(plan, split)));
                }
            }
            var actual = string.Join("\n", outputs.Select(o => name + "/" + o.Item1 + " " + Sha256(o.Item2)));
            TestContext.Progress.WriteLine(actual);
            var expected = string.Join("\n", outputs.Select(o => name + "/" + o.Item1 + " " + (Expected.TryGetValue(name + "/" + o.Item1, out var e) ? e : "?")));
            Assert.That(actual, Is.EqualTo(expected));
        }

        // dataset_config.json records the imported file's path, which depends on where the repository is, and the
        // plugin's version, which changes with every release: the sums were taken at 0.1.0.
        static string WithoutFixturePath(string config)
        {
            var quoted = Newtonsoft.Json.JsonConvert.ToString(Fixtures.LegoTrainPath);
            return config.Replace(quoted.Substring(1, quoted.Length - 2), "LEGO")
                .Replace("\"pluginVersion\": \"" + PluginInfo.Version + "\"", "\"pluginVersion\": \"0.1.0\"");
        }

        /// <summary>
        /// The config without its <c>unity_frame</c> block (added by issue 34 after these sums were taken, and checked by
        /// UnityFrameRecordTests): everything else must stay byte for byte what it was.
        /// </summary>
        static string WithoutUnityFrame(string config)
        {
            var start = config.IndexOf("\n  \"" + UnityFrameRecord.Key + "\": {", StringComparison.Ordinal);
            Assert.That(start, Is.GreaterThan(0), "every config records unity_frame");
            var end = config.IndexOf("\n  },", start, StringComparison.Ordinal) + "\n  },".Length;
            return config.Remove(start, end - start);
        }

        static byte[] Utf8(string text) => new UTF8Encoding(false).GetBytes(text);

        static string Sha256(byte[] bytes)
        {
            using (var sha = SHA256.Create())
                return string.Concat(sha.ComputeHash(bytes).Select(b => b.ToString("x2")));
        }
    }
}
