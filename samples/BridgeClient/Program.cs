// A Grasshopper-style client of the Machina Bridge: see BridgeClientSample.cs.
return await SampleHost.RunAsync(args, Machina.Samples.BridgeClientSample.RunAsync);
