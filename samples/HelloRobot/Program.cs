// The paper's "Hello Robot" (Code Sample 1): see HelloRobotSample.cs. Ctrl+C stops it cleanly.
return await SampleHost.RunAsync(args, Machina.Samples.HelloRobotSample.RunAsync);
