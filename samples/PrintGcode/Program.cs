// A small 3D print (a square vase) compiled to G-code: see PrintGcodeSample.cs.
return await SampleHost.RunAsync(args, Machina.Samples.PrintGcodeSample.RunAsync);
