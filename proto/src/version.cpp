// Placeholder translation unit so the target exists before the JSON mapping lands.
namespace radiant::proto {
int version() { return 1; }
}  // namespace radiant::proto
