// A tool on a path of its own (-die_path, -die_path_turn: tool/path.hpp): moved and turned along the piece ahead
// of its stroke, piece by piece.
#include "tubeform/tool/motion.hpp"

namespace tf {

namespace {
class Path : public Motion {
public:
  explicit Path(const ToolPath &path) : path_(path), d_(path.Motion(0)), spin_(path.Spin(0)) {}
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Path>(*this); }
  std::string Kind() const override { return "path"; }
  Vec2 Offset(double s) const override { return path_.At(s); }
  double Turn(double s) const override { return path_.Turn(s); }
  Vec2 Direction() const override { return d_; }
  double Spin() const override { return spin_; }
  void Follow(double s) override { d_ = path_.Motion(s), spin_ = path_.Spin(s); }
  std::vector<double> Kinks() const override { return path_.Turns(); }
  void Map(const TurnMap &map) override
  {
    path_ = path_.Mapped(map), d_ = map(d_);
    spin_ = map.det() * spin_;
  }

private:
  ToolPath path_;
  Vec2 d_;      // the motion per unit stroke on the piece followed
  double spin_; // and the turn
};
} // namespace

std::unique_ptr<Motion> PathMotion(const ToolPath &path) { return std::make_unique<Path>(path); }

const MotionKind &PathKind()
{
  static const MotionKind kind{"path", {}, nullptr, [](const MotionSpec &s, MotionHandle &m) {
                                 return s.path.empty() ? "a path with no points"
                                                       : (m = PathMotion(s.path), std::string());
                               }};
  return kind;
}

} // namespace tf
